// outfile: atomic output files and path checks (see outfile.h)
#include "outfile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace mjbtool {

// "--csv: cannot write out.csv: why"
static std::string cannot(const std::string& what, const std::string& path,
                          const std::string& why) {
  return what + ": cannot write " + path + ": " + why;
}

static std::string sysErr(const std::string& what, const std::string& path, const char* doing) {
  return cannot(what, path, std::string("cannot ") + doing + ": " + std::strerror(errno));
}

static std::string dirOf(const std::string& path) {
  std::string d = fs::path(path).parent_path().string();
  return d.empty() ? "." : d;
}

static std::string tmpDir() {
  const char* t = std::getenv("TMPDIR");
  return t && *t ? t : "/tmp";
}

OutFile::OutFile(OutFile&& o) noexcept
    : f_(o.f_), path_(std::move(o.path_)), target_(std::move(o.target_)),
      tmp_(std::move(o.tmp_)), what_(std::move(o.what_)), direct_(o.direct_) {
  o.f_ = nullptr;
  o.tmp_.clear();
}

OutFile::~OutFile() { discard(); }

void OutFile::discard() {
  if (f_) std::fclose(f_);
  f_ = nullptr;
  if (!tmp_.empty()) ::unlink(tmp_.c_str());
  tmp_.clear();
}

bool OutFile::open(const std::string& path, const std::string& what, std::string* err) {
  discard();
  path_ = path;
  what_ = what;
  direct_ = false;
  if (path.empty()) {
    *err = what + ": empty file name";
    return false;
  }
  std::string dir;
  mode_t mode;
  struct stat st;
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) {
      *err = cannot(what, path, "it is a directory; give a file name");
      return false;
    }
    if (S_ISREG(st.st_mode)) {
      // replace the file a link points to, not the link
      std::error_code ec;
      target_ = fs::canonical(path, ec).string();
      if (ec) target_ = path;
      dir = dirOf(target_);
      mode = st.st_mode & 07777;
    } else {
      direct_ = true;  // device, pipe, socket: written in place at commit
      target_ = path;
      dir = tmpDir();
      mode = 0600;
    }
  } else {
    struct stat lst;
    if (::lstat(path.c_str(), &lst) == 0) {
      *err = cannot(what, path, "it is a symbolic link to a missing file; remove it or give "
                                "another name");
      return false;
    }
    target_ = path;
    dir = dirOf(path);
    mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  std::string name = fs::path(target_).filename().string();
  std::string ext = fs::path(name).extension().string();
  if (ext.size() > 16) ext.clear();
  std::string t = dir + "/." + name + ".tmp-XXXXXX" + ext;
  std::vector<char> buf(t.begin(), t.end());
  buf.push_back(0);
  int fd = ::mkstemps(buf.data(), (int)ext.size());
  if (fd < 0) {
    *err = sysErr(what, path, ("create a temporary file in " + dir).c_str());
    return false;
  }
  tmp_ = buf.data();
  ::fchmod(fd, mode);
  f_ = ::fdopen(fd, "wb");
  if (!f_) {
    ::close(fd);
    *err = sysErr(what, path, "open its temporary file");
    discard();
    return false;
  }
  return true;
}

// copy the temporary file's bytes to a non-regular target, every write checked
static bool copyTo(const std::string& from, const std::string& to, std::string* why) {
  FILE* in = std::fopen(from.c_str(), "rb");
  if (!in) {
    *why = std::string("cannot read the temporary file: ") + std::strerror(errno);
    return false;
  }
  FILE* out = std::fopen(to.c_str(), "wb");
  if (!out) {
    *why = std::strerror(errno);
    std::fclose(in);
    return false;
  }
  char buf[1 << 16];
  bool ok = true;
  size_t n;
  while (ok && (n = std::fread(buf, 1, sizeof(buf), in)) > 0) {
    ok = std::fwrite(buf, 1, n, out) == n;
  }
  ok = ok && !std::ferror(in) && std::fflush(out) == 0 && !std::ferror(out);
  int e = errno;
  std::fclose(in);
  if (std::fclose(out) != 0 && ok) {
    ok = false;
    e = errno;
  }
  if (!ok) *why = std::strerror(e);
  return ok;
}

bool OutFile::commit(std::string* err) {
  if (!f_) {
    *err = what_ + " " + path_ + ": not open";
    return false;
  }
  errno = 0;
  bool ok = std::fflush(f_) == 0 && !std::ferror(f_);
  int e = errno;
  if (std::fclose(f_) != 0 && ok) {
    ok = false;
    e = errno;
  }
  f_ = nullptr;
  if (!ok) {
    *err = cannot(what_, path_, std::strerror(e ? e : EIO));
    discard();
    return false;
  }
  if (direct_) {
    std::string why;
    ok = copyTo(tmp_, target_, &why);
    discard();
    if (!ok) *err = cannot(what_, path_, why);
    return ok;
  }
  if (std::rename(tmp_.c_str(), target_.c_str()) != 0) {
    *err = sysErr(what_, path_, "rename the finished temporary file onto it");
    discard();
    return false;
  }
  tmp_.clear();
  return true;
}

bool checkWritable(const std::string& path, const std::string& what, std::string* err) {
  if (path.empty()) {
    *err = what + ": empty file name";
    return false;
  }
  struct stat st;
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) {
      *err = cannot(what, path, "it is a directory; give a file name");
      return false;
    }
    if (::access(path.c_str(), W_OK) != 0) {
      *err = cannot(what, path, std::strerror(errno));
      return false;
    }
    if (!S_ISREG(st.st_mode)) return true;
    std::error_code ec;
    std::string dir = dirOf(fs::canonical(path, ec).string());
    if (::access(dir.c_str(), W_OK | X_OK) != 0) {
      *err = cannot(what, path, "its directory " + dir + " is not writable (" +
                                    std::strerror(errno) + "), so it cannot be replaced safely");
      return false;
    }
    return true;
  }
  std::string dir = dirOf(path);
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
    *err = cannot(what, path, "directory " + dir + " does not exist; create it first");
    return false;
  }
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    *err = cannot(what, path, "directory " + dir + " is not writable (" +
                                  std::strerror(errno) + ")");
    return false;
  }
  return true;
}

namespace {
struct Id {
  bool exists = false, special = false;
  dev_t dev = 0;
  ino_t ino = 0;
  std::string canon;  // not existing: canonical directory + name
};

Id idOf(const std::string& path) {
  Id id;
  struct stat st;
  if (::stat(path.c_str(), &st) == 0) {
    id.exists = true;
    id.special = !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
    id.dev = st.st_dev;
    id.ino = st.st_ino;
  } else {
    std::error_code ec;
    fs::path p = fs::absolute(path, ec);
    fs::path c = fs::weakly_canonical(p, ec);
    id.canon = ec ? p.lexically_normal().string() : c.string();
  }
  return id;
}
}  // namespace

bool checkDistinct(const std::vector<PathUse>& uses, std::string* err) {
  std::vector<Id> ids;
  for (const PathUse& u : uses) ids.push_back(idOf(u.path));
  for (size_t i = 0; i < uses.size(); i++) {
    if (!uses[i].output) continue;
    for (size_t j = 0; j < uses.size(); j++) {
      if (j == i || (uses[j].output && j < i)) continue;
      const Id &a = ids[i], &b = ids[j];
      bool same = a.exists == b.exists &&
                  (a.exists ? a.dev == b.dev && a.ino == b.ino : a.canon == b.canon);
      if (!same) continue;
      if (uses[j].output) {
        if (a.special) continue;  // /dev/null twice
        *err = uses[i].what + " " + uses[i].path + " and " + uses[j].what + " " + uses[j].path +
               " are the same file; give each output its own file";
      } else {
        *err = uses[i].what + " " + uses[i].path + " is the same file as the " + uses[j].what +
               " " + uses[j].path + "; refusing to overwrite an input, choose another name";
      }
      return false;
    }
  }
  return true;
}

}  // namespace mjbtool
