// mjbuoy-sweep: atomic output files (atomic.h)
#include "atomic.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>

namespace atomicfile {

std::string tempBeside(const std::string& path) {
  // host and pid: processes on several nodes may write into one shared directory
  static unsigned long n = 0;
  char host[256] = "";
  gethostname(host, sizeof(host) - 1);
  return path + ".tmp." + host + "." + std::to_string(getpid()) + "." + std::to_string(n++);
}

bool commit(const std::string& path, const std::function<bool(const std::string& tmp)>& fill,
            std::string* err) {
  std::string tmp = tempBeside(path);
  if (!fill(tmp)) {
    std::remove(tmp.c_str());
    if (err) *err = "cannot write " + tmp + ": check the directory exists and is writable";
    return false;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    int e = errno;
    std::remove(tmp.c_str());
    if (err) *err = "cannot rename " + tmp + " to " + path + ": " + std::strerror(e);
    return false;
  }
  return true;
}

bool write(const std::string& path, const std::string& data, std::string* err) {
  return commit(path, [&](const std::string& tmp) {
    FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) return false;
    bool ok = std::fwrite(data.data(), 1, data.size(), f) == data.size();
    ok = (std::fflush(f) == 0) && ok;
    ok = (fsync(fileno(f)) == 0) && ok;  // the data is on disk before the rename
    return (std::fclose(f) == 0) && ok;
  }, err);
}

}  // namespace atomicfile
