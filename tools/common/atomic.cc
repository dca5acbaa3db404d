// mjbuoy-sweep's output files, through the tools' shared atomic output
// (tools/common/outfile.h): temporary file beside the target, every write checked,
// renamed into place only when complete
#include "atomic.h"

#include <cstdio>

#include "outfile.h"

namespace atomicfile {

bool write(const std::string& path, const std::string& data, std::string* err) {
  mjbtool::OutFile o;
  if (!o.open(path, path, err)) return false;
  if (std::fwrite(data.data(), 1, data.size(), o.file()) != data.size()) {
    *err = "cannot write " + path;
    return false;
  }
  return o.commit(err);
}

bool commit(const std::string& path, const std::function<bool(const std::string& tmp)>& fill,
            std::string* err) {
  mjbtool::OutFile o;
  if (!o.open(path, path, err)) return false;
  if (!fill(o.tmpPath())) {
    *err = "cannot write " + path;
    return false;
  }
  return o.commit(err);
}

}  // namespace atomicfile
