#pragma once
// Where the sun is seen from a place on the Earth at a UTC instant, from ERFA (the IAU's SOFA
// routines, Debian's liberfa-dev): the Earth's orbit (eraEpv00, within 4.6 km of JPL's DE405 over
// 1900-2100), annual aberration, the IAU 2006/2000A precession-nutation, the Earth's rotation and
// diurnal aberration, then the parallax of the sun's 1 au distance from the observer's place on
// the WGS84 ellipsoid. Angles are topocentric, about the local (geodetic) vertical.
//
// Geometric by default: the direction of a straight line to the sun, which is what aerial's
// atmosphere model takes (its rays do not bend). The sun a person sees is raised by refraction,
// 0.5 degrees at the horizon; `refraction` adds ERFA's model (eraRefco, A tan z + B tan^3 z),
// which ERFA states is good to about 0.1 arcsecond down to 15 degrees above the horizon and holds
// the elevation at 2.9 degrees below that (eraAtioq), so near the horizon it is only indicative.
#include <optional>

namespace aerial::astronomy {

// A UTC date and time (proleptic Gregorian calendar).
struct UtcTime {
  int year = 2000, month = 1, day = 1, hour = 0, minute = 0;
  double second = 0.0;
};

struct Observer {
  double latitude_deg = 0.0;   // geodetic, north positive
  double longitude_deg = 0.0;  // east positive
  double height_m = 0.0;       // above the WGS84 ellipsoid
};

struct Refraction {
  double pressure_hpa = 1013.25;
  double temperature_c = 15.0;
  double relative_humidity = 0.0;  // 0 to 1
};

struct SunPositionOptions {
  // UT1 - UTC in seconds: within 0.9 s by the definition of UTC, so 0 turns the sky by at most
  // 0.004 degrees; IERS Bulletin A publishes it for those who need better.
  double dut1_s = 0.0;
  std::optional<Refraction> refraction;  // none: the geometric direction
};

struct SunPosition {
  double zenith_deg = 0.0;   // from the local vertical
  double azimuth_deg = 0.0;  // compass: 0 north, 90 east, in [0, 360)
  double distance_au = 0.0;  // from the Earth's centre
};

// Throws aerial::Error naming "UTC time" for a date and time ERFA refuses (eraDtf2d).
SunPosition ComputeSunPosition(const UtcTime& utc, const Observer& observer,
                               const SunPositionOptions& options = {});

}  // namespace aerial::astronomy
