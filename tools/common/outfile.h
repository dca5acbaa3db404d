// outfile: the tools' output files. Nothing a tool writes replaces a file
// until it is complete: the bytes go to a temporary file beside the target,
// every write and the close are checked, and only then is the temporary
// renamed onto the target. A target that is an existing device, pipe or
// other non-regular file (/dev/null, /dev/stdout, /dev/full) cannot be
// renamed onto: the temporary then lives in $TMPDIR and its bytes are
// copied to the target at commit, every write checked. Outputs are checked
// against the inputs and against each other first (same file, also through
// links).
#ifndef MJBUOY_TOOLS_OUTFILE_H_
#define MJBUOY_TOOLS_OUTFILE_H_

#include <cstdio>
#include <string>
#include <vector>

namespace mjbtool {

// one output file, written atomically
class OutFile {
 public:
  OutFile() = default;
  OutFile(const OutFile&) = delete;
  OutFile& operator=(const OutFile&) = delete;
  OutFile(OutFile&& o) noexcept;
  ~OutFile();  // not committed: the temporary file is removed

  // start writing path; what names it in messages ("--csv"). The temporary
  // file keeps the target's extension (programs that pick a format by it)
  bool open(const std::string& path, const std::string& what, std::string* err);
  FILE* file() const { return f_; }
  // the temporary file, for programs that write it themselves (gnuplot,
  // ffmpeg): they replace its content by path
  const std::string& tmpPath() const { return tmp_; }
  const std::string& path() const { return path_; }
  bool isOpen() const { return f_ != nullptr; }
  // flush and close with every error checked, then rename onto the target
  // (or copy to a non-regular target); false with the reason
  bool commit(std::string* err);
  // drop the temporary file
  void discard();

 private:
  FILE* f_ = nullptr;
  std::string path_, target_, tmp_, what_;
  bool direct_ = false;  // non-regular target: copy at commit
};

// can path be written (an existing file, or a new one in an existing,
// writable directory), checked without creating or truncating anything
bool checkWritable(const std::string& path, const std::string& what, std::string* err);

// a file a tool reads or writes, named in messages by what ("--csv", "model")
struct PathUse {
  std::string path, what;
  bool output = false;
};

// refuses an output that is one of the inputs or another output: the same
// file (st_dev and st_ino, so also through links) or, for a file that does
// not exist yet, the same canonical directory and name. Devices, pipes and
// sockets may be named as several outputs (/dev/null twice)
bool checkDistinct(const std::vector<PathUse>& uses, std::string* err);

}  // namespace mjbtool

#endif  // MJBUOY_TOOLS_OUTFILE_H_
