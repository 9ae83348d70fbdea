// A shared library linking aerial (as an engine plugin would): it links only if aerial's static
// library is position-independent.
#include <aerial/atmosphere.h>

extern "C" double PluginPlanetRadiusM() { return aerial::AtmosphereParameters::Earth().bottom_radius_m; }
