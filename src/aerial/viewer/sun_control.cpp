#include "aerial/viewer/sun_control.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace aerial::viewer {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

double WrapDegrees(double degrees) {
  double wrapped = std::fmod(degrees, 360.0);
  return wrapped < 0.0 ? wrapped + 360.0 : wrapped;
}

}  // namespace

void SteerSun(Sun& sun, double d_azimuth_deg, double d_zenith_deg, double max_zenith_deg) {
  sun.azimuth_deg = WrapDegrees(sun.azimuth_deg + d_azimuth_deg);
  sun.zenith_deg = std::clamp(sun.zenith_deg + d_zenith_deg, 0.0, max_zenith_deg);
}

Sun SunAtSolarTime(double hours, double latitude_deg, double declination_deg) {
  double h = (hours - 12.0) * 15.0 / kDegrees;
  double lat = latitude_deg / kDegrees, dec = declination_deg / kDegrees;
  double cos_zenith = std::sin(lat) * std::sin(dec) + std::cos(lat) * std::cos(dec) * std::cos(h);
  double azimuth = std::atan2(std::sin(h) * std::cos(dec),
                              std::cos(h) * std::sin(lat) * std::cos(dec) - std::sin(dec) * std::cos(lat));
  return {.zenith_deg = std::acos(std::clamp(cos_zenith, -1.0, 1.0)) * kDegrees,
          .azimuth_deg = WrapDegrees(azimuth * kDegrees + 180.0)};
}

}  // namespace aerial::viewer
