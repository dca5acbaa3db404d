// moorconfig: the MJCF entries of mooring lines, line types and the seabed
// (docs/mooring.md "MJCF"), read at attach
#ifndef MJBUOY_MOORCONFIG_H_
#define MJBUOY_MOORCONFIG_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "mooring/mooring.h"
#include "sea/sea.h"

namespace mjb {

// whether the key after "mjbuoy." is one of these entries (line.*,
// linetype.*, seabed.*)
bool isMoorEntry(const char* key);

// whether m has any mjbuoy.line.* entry
bool hasLines(const mjModel* m);

// read them into mo for the sea (its depth and level place the bed) and m's
// sites at qpos0; "" or the first error, naming the line or type, the field,
// the value and the accepted range; warn gets load-time warnings
std::string parseMooring(const mjModel* m, const Sea& sea, Mooring* mo,
                         std::vector<std::string>* warn);

}  // namespace mjb

#endif  // MJBUOY_MOORCONFIG_H_
