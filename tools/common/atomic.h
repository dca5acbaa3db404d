// mjbuoy-sweep: atomic output files, a thin layer over tools/common/outfile.h for
// whole strings and for programs that write a file by name (gnuplot). A
// reader (or a resumed sweep) sees the old file or the complete new one.
#ifndef MJBUOY_TOOLS_ATOMIC_H_
#define MJBUOY_TOOLS_ATOMIC_H_

#include <functional>
#include <string>

namespace atomicfile {

// write data to path atomically; false with *err set on failure
bool write(const std::string& path, const std::string& data, std::string* err);

// let fill write the temporary file by its name (false: failed), then
// rename it to path
bool commit(const std::string& path, const std::function<bool(const std::string& tmp)>& fill,
            std::string* err);

}  // namespace atomicfile

#endif  // MJBUOY_TOOLS_ATOMIC_H_
