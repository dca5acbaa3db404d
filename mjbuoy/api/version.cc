// library version, compiled from the generated mjbuoy_version.h
#include "mjbuoy.h"

int mjb_version(void) { return MJBUOY_VERSION; }

const char* mjb_versionString(void) { return MJBUOY_VERSION_STRING; }
