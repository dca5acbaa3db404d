// seasetter: mjb_setSea's validation and in-place rewrite of the sea
#ifndef MJBUOY_SEASETTER_H_
#define MJBUOY_SEASETTER_H_

#include "api/buoy.h"

namespace mjb {

// validate sea, then replace b's components, current and wind in place
// (within b->wcap: no allocation); 0 with a message in error on bad input
int setSea(Buoy* b, const mjbSea& sea, char* error, int error_sz);

}  // namespace mjb

#endif  // MJBUOY_SEASETTER_H_
