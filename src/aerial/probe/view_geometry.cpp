#include "aerial/view_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "aerial/core/format_number.h"
#include "aerial/error.h"

namespace aerial {
namespace {

void CheckAngle(const char* field, double value, double low, double high) {
  if (!std::isfinite(value) || value < low || value > high)
    throw Error(field, FormatNumber(value),
                "degrees in [" + FormatNumber(low) + ", " + FormatNumber(high) + "]");
}

}  // namespace

void ValidateViewAngles(const ViewAngles& view, const AtmosphereParameters& atmosphere) {
  double thickness = atmosphere.top_radius_m - atmosphere.bottom_radius_m;
  if (!std::isfinite(view.altitude_m) || view.altitude_m < 0.0 || view.altitude_m > thickness)
    throw Error("ViewAngles::altitude_m", FormatNumber(view.altitude_m),
                "meters in [0, " + FormatNumber(thickness) + "] (ground to the top of the atmosphere)");
  CheckAngle("ViewAngles::view_zenith_deg", view.view_zenith_deg, 0.0, 180.0);
  CheckAngle("ViewAngles::sun_zenith_deg", view.sun_zenith_deg, 0.0, 180.0);
  CheckAngle("ViewAngles::azimuth_deg", view.azimuth_deg, -360.0, 360.0);
}

RayParameters ToRayParameters(const ViewAngles& view, const AtmosphereParameters& atmosphere) {
  constexpr double kDegree = std::numbers::pi / 180.0;
  double mu = std::cos(view.view_zenith_deg * kDegree);
  double mu_s = std::cos(view.sun_zenith_deg * kDegree);
  double nu = mu * mu_s + std::sqrt(std::max(0.0, (1.0 - mu * mu) * (1.0 - mu_s * mu_s))) *
                              std::cos(view.azimuth_deg * kDegree);
  return {atmosphere.bottom_radius_m + view.altitude_m, mu, mu_s, std::clamp(nu, -1.0, 1.0)};
}

}  // namespace aerial
