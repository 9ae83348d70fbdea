#include "aerial/scene/scene_limits.h"

#include <cmath>

#include "aerial/error.h"

namespace aerial {
namespace {

void Check(bool ok, double value, const std::string& field, const std::string& allowed,
           const std::string& where) {
  if (!ok) throw Error(field, FormatNumber(value), allowed, where);
}

}  // namespace

void CheckCameraPosition(const glm::dvec3& p, double planet_radius_m, const std::string& field,
                         const std::string& where) {
  const char* axes[] = {"[0]", "[1]", "[2]"};
  for (int i = 0; i < 3; ++i)
    Check(std::isfinite(p[i]), p[i], field + axes[i], "a finite number (m)", where);
  double altitude = glm::length(p - glm::dvec3(0.0, 0.0, -planet_radius_m)) - planet_radius_m;
  if (!(altitude >= -500.0 && altitude <= 100e3)) {
    throw Error(field,
                "[" + FormatNumber(p.x) + ", " + FormatNumber(p.y) + ", " + FormatNumber(p.z) +
                    "] (altitude " + FormatNumber(altitude) + " m)",
                "an altitude above the planet's sphere in [-500, 100000] m", where);
  }
}

void CheckAzimuthDeg(double degrees, const std::string& field, const std::string& where) {
  Check(std::fabs(degrees) <= kMaxAzimuthDeg, degrees, field,
        "an angle in [-" + FormatNumber(kMaxAzimuthDeg) + ", " + FormatNumber(kMaxAzimuthDeg) +
            "] degrees (compass angles wrap)",
        where);
}

void CheckPitchDeg(double degrees, const std::string& field, const std::string& where) {
  Check(degrees >= -90.0 && degrees <= 90.0, degrees, field, "[-90, 90] degrees", where);
}

void CheckFovDeg(double degrees, const std::string& field, const std::string& where) {
  Check(degrees > 1.0 && degrees < 170.0, degrees, field, "(1, 170) degrees, open", where);
}

void CheckNearM(double meters, const std::string& field, const std::string& where) {
  // Compared in double: the bounds are far inside float's range, so the float the projection
  // receives is in range exactly when the double is (up to rounding at the bounds themselves).
  Check(meters >= 1e-3 && meters <= 1e3, meters, field, "[0.001, 1000] m", where);
}

void CheckZenithDeg(double degrees, const std::string& field, const std::string& where) {
  Check(degrees >= 0.0 && degrees <= 180.0, degrees, field, "[0, 180] degrees", where);
}

void CheckPlacedDistance(double farthest_m, const std::string& field, const std::string& value,
                         const std::string& where) {
  if (!(farthest_m <= kMaxSceneDistanceM)) {
    throw Error(field, value + " (places a vertex " + FormatNumber(farthest_m) + " m from the origin)",
                "a placement that keeps every vertex within " + FormatNumber(kMaxSceneDistanceM) +
                    " m of the scene origin",
                where);
  }
}

}  // namespace aerial
