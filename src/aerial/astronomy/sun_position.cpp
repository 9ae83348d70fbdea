#include "aerial/astronomy/sun_position.h"

#include <cmath>
#include <cstdio>

#include <erfa.h>
#include <erfam.h>

#include "aerial/error.h"

namespace aerial::astronomy {
namespace {

constexpr double kWavelengthUm = 0.55;  // refraction's wavelength: the middle of the visible

struct Observed {
  double azimuth_rad, zenith_rad;
};

// CIRS (ri, di) seen from the observer: Earth rotation, polar motion taken as 0, diurnal
// aberration, and refraction at pressure_hpa (0: none), for a source at infinity.
Observed ObserveCirs(double ri, double di, double utc1, double utc2, const Observer& observer,
                     double dut1_s, const Refraction& air, double pressure_hpa) {
  eraASTROM astrom;
  eraApio13(utc1, utc2, dut1_s, observer.longitude_deg * ERFA_DD2R, observer.latitude_deg * ERFA_DD2R,
            observer.height_m, 0.0, 0.0, pressure_hpa, air.temperature_c, air.relative_humidity,
            kWavelengthUm, &astrom);
  double azimuth, zenith, hour_angle, declination, right_ascension;
  eraAtioq(ri, di, &astrom, &azimuth, &zenith, &hour_angle, &declination, &right_ascension);
  return {azimuth, zenith};
}

}  // namespace

SunPosition ComputeSunPosition(const UtcTime& utc, const Observer& observer, const SunPositionOptions& options) {
  double utc1, utc2;
  if (eraDtf2d("UTC", utc.year, utc.month, utc.day, utc.hour, utc.minute, utc.second, &utc1, &utc2) < 0) {
    char text[64];
    std::snprintf(text, sizeof text, "%04d-%02d-%02d %02d:%02d:%06.3f", utc.year, utc.month, utc.day, utc.hour,
                  utc.minute, utc.second);
    throw Error("UTC time", text, "a date and time of the Gregorian calendar");
  }
  double tai1, tai2, tt1, tt2;
  eraUtctai(utc1, utc2, &tai1, &tai2);
  eraTaitt(tai1, tai2, &tt1, &tt2);

  // The Earth's heliocentric and barycentric position and velocity (au, au/day, BCRS): the sun
  // seen from the geocentre is the heliocentric position reversed.
  double heliocentric[2][3], barycentric[2][3];
  eraEpv00(tt1, tt2, heliocentric, barycentric);
  double toward_sun[3], distance_au;
  eraSxp(-1.0, heliocentric[0], toward_sun);
  eraPn(toward_sun, &distance_au, toward_sun);
  // Annual aberration, from the Earth's barycentric velocity in units of c.
  double velocity[3];
  eraSxp(ERFA_AULT / ERFA_DAYSEC, barycentric[1], velocity);
  double apparent[3];
  eraAb(toward_sun, velocity, distance_au, std::sqrt(1.0 - eraPdp(velocity, velocity)), apparent);
  // GCRS to CIRS: frame bias, precession and nutation (IAU 2006/2000A).
  double gcrs_to_cirs[3][3], cirs[3], ri, di;
  eraC2i06a(tt1, tt2, gcrs_to_cirs);
  eraRxp(gcrs_to_cirs, apparent, cirs);
  eraC2s(cirs, &ri, &di);

  const Refraction air = options.refraction.value_or(Refraction{});
  const Observed geocentric = ObserveCirs(ri, di, utc1, utc2, observer, options.dut1_s, air, 0.0);

  // Parallax: the sun 1 au from the geocentre, seen from the observer (up to 8.8 arcseconds).
  // The observer's geocentric position (ITRS, m) in the local east-north-up frame.
  const double longitude = observer.longitude_deg * ERFA_DD2R, latitude = observer.latitude_deg * ERFA_DD2R;
  double position[3];
  eraGd2gc(ERFA_WGS84, longitude, latitude, observer.height_m, position);
  double east[3] = {-std::sin(longitude), std::cos(longitude), 0.0};
  double north[3] = {-std::sin(latitude) * std::cos(longitude), -std::sin(latitude) * std::sin(longitude),
                           std::cos(latitude)};
  double up[3] = {std::cos(latitude) * std::cos(longitude), std::cos(latitude) * std::sin(longitude),
                        std::sin(latitude)};
  const double distance_m = distance_au * ERFA_DAU;
  const double sin_zenith = std::sin(geocentric.zenith_rad);
  const double sun[3] = {distance_m * sin_zenith * std::sin(geocentric.azimuth_rad) - eraPdp(position, east),
                         distance_m * sin_zenith * std::cos(geocentric.azimuth_rad) - eraPdp(position, north),
                         distance_m * std::cos(geocentric.zenith_rad) - eraPdp(position, up)};
  double zenith = std::atan2(std::hypot(sun[0], sun[1]), sun[2]);
  const double azimuth = eraAnp(std::atan2(sun[0], sun[1]));

  if (options.refraction) {
    // ERFA's refraction at the geocentric direction: it changes by 0.01 arcsecond over the
    // parallax's few arcseconds.
    const Observed refracted =
        ObserveCirs(ri, di, utc1, utc2, observer, options.dut1_s, air, options.refraction->pressure_hpa);
    zenith += refracted.zenith_rad - geocentric.zenith_rad;
  }
  return {zenith * ERFA_DR2D, azimuth * ERFA_DR2D, distance_au};
}

}  // namespace aerial::astronomy
