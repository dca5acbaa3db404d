// mjbuoy-sweep: atomic output files. Every output is written to a
// temporary file beside its target and renamed over it, so a reader (or a
// resumed sweep) sees the old file or the complete new one, never a part.
// Small on purpose: the shared tools/outfile module replaces it at merge.
#ifndef MJBUOY_TOOLS_ATOMIC_H_
#define MJBUOY_TOOLS_ATOMIC_H_

#include <functional>
#include <string>

namespace atomicfile {

// a temporary name in the target's directory (same file system: rename works)
std::string tempBeside(const std::string& path);

// write data to path atomically; false with *err set on failure
bool write(const std::string& path, const std::string& data, std::string* err);

// let fill write the temporary file (false: failed), then rename it to path
bool commit(const std::string& path, const std::function<bool(const std::string& tmp)>& fill,
            std::string* err);

}  // namespace atomicfile

#endif  // MJBUOY_TOOLS_ATOMIC_H_
