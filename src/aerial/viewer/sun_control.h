#pragma once
// Where the sun is: moved directly by the arrow keys and the mouse, or set from a time of day.
#include "aerial/scene.h"

namespace aerial::viewer {

// Turns the sun by the given angles; the zenith angle stays in [0, max_zenith_deg] (the tables
// cover suns down to acos(mu_s_min), 120 degrees for "earth"), the azimuth wraps to [0, 360).
void SteerSun(Sun& sun, double d_azimuth_deg, double d_zenith_deg, double max_zenith_deg);

// The sun at a local solar time (hours, 12 = solar noon) seen from latitude latitude_deg on a day
// of solar declination declination_deg (0 at the equinoxes, +-23.44 at the solstices). Standard
// spherical astronomy, no refraction: with hour angle H = 15 deg (t - 12),
//   cos zenith = sin(lat) sin(dec) + cos(lat) cos(dec) cos(H),
//   azimuth    = atan2(sin H cos dec, cos H sin lat cos dec - sin dec cos lat) + 180 deg,
// a compass bearing (0 north, 90 east), so that the morning sun is in the east.
Sun SunAtSolarTime(double hours, double latitude_deg, double declination_deg);

}  // namespace aerial::viewer
