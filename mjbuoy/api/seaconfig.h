// seaconfig: the MJCF entries of irregular seas and wind (docs/mjcf.md
// sections 7 and 8), called from parseConfig
#ifndef MJBUOY_SEACONFIG_H_
#define MJBUOY_SEACONFIG_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

namespace mjb {

struct Config;

// whether the key after "mjbuoy." is one of these entries (spectrum.*,
// wind.*, sea.capacity)
bool isSeaExtra(const char* key);

// read them into c: spectra expanded and appended to c->sea.waves, the
// wind parameters, the component capacity; "" or the first error
std::string parseSeaExtra(const mjModel* m, const std::vector<int>& hulls, Config* c);

}  // namespace mjb

#endif  // MJBUOY_SEACONFIG_H_
