#include "froxel/sun_high_variant.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace aerial {
namespace {

// The tables' mu_s axis (mappings.glsl).
constexpr double kMuSDensest = -0.1, kMuSSpread = 7.0;

// The camera's distance from the planet's centre and the sine of the sun's elevation there.
bool CameraAndSun(const FrameUniforms& frame, double* r, double* sun_sine) {
  const glm::dvec3 camera(frame.camera_planet_position[0], frame.camera_planet_position[1],
                          frame.camera_planet_position[2]);
  const glm::dvec3 sun(frame.sun_direction[0], frame.sun_direction[1], frame.sun_direction[2]);
  *r = glm::length(camera);
  const double sun_length = glm::length(sun);
  if (!(*r > 0.0) || !(sun_length > 0.0)) return false;
  *sun_sine = std::clamp(glm::dot(camera / *r, sun / sun_length), -1.0, 1.0);
  return true;
}

}  // namespace

double UnitRangeFromMuS(double mu_s, double mu_s_min) {
  const double low = std::atan(kMuSSpread * (mu_s_min - kMuSDensest));
  const double high = std::atan(kMuSSpread * (1.0 - kMuSDensest));
  return std::clamp((std::atan(kMuSSpread * (mu_s - kMuSDensest)) - low) / (high - low), 0.0, 1.0);
}

double MuSFromUnitRange(double x, double mu_s_min) {
  const double low = std::atan(kMuSSpread * (mu_s_min - kMuSDensest));
  const double high = std::atan(kMuSSpread * (1.0 - kMuSDensest));
  return std::clamp(kMuSDensest + std::tan(low + x * (high - low)) / kMuSSpread, -1.0, 1.0);
}

bool SunHighWithin(double camera_radius_m, double sun_sine, double distance_m, double bottom_radius_m) {
  if (!(camera_radius_m > 0.0) || !(bottom_radius_m > 0.0) || !(distance_m >= 0.0) || !(std::abs(sun_sine) <= 1.0))
    return false;
  // A point d from the camera, both at least R from the planet's centre (the marches stop at the
  // ground), sees the centre at an angle theta from the camera with sin theta <= d / R (law of
  // sines), and its horizontal is turned by theta: the sun's elevation there is at least the
  // camera's minus theta.
  const double nearest_radius = std::min(camera_radius_m, bottom_radius_m);
  const double arc = std::asin(std::min(distance_m / nearest_radius, 1.0));
  return std::sin(std::asin(sun_sine) - arc) > kSunDiscOneTapSine + 0.005;
}

bool SunHighWithin(const FrameUniforms& frame, double distance_m, double bottom_radius_m) {
  double r = 0.0, sun_sine = 0.0;
  return CameraAndSun(frame, &r, &sun_sine) && SunHighWithin(r, sun_sine, distance_m, bottom_radius_m);
}

double LongestSkyRayM(double r, double bottom_radius_m, double top_radius_m) {
  const double R2 = bottom_radius_m * bottom_radius_m;
  return std::sqrt(std::max(r * r - R2, 0.0)) + std::sqrt(std::max(top_radius_m * top_radius_m - R2, 0.0));
}

double LowestSkyCorrectionSunSine(double mu_s, double mu_s_min, int mu_s_texels) {
  const double last = double(std::max(mu_s_texels, 2) - 1);
  // GetTexelBlend's lower texel, floor(x (n - 1)), then the one below it.
  const double lower = std::floor(UnitRangeFromMuS(mu_s, mu_s_min) * last - 0.01);
  return std::min(mu_s, MuSFromUnitRange(std::max(lower - 1.0, 0.0) / last, mu_s_min));
}

bool SunHighOverEverySkyRay(const FrameUniforms& frame, const AtmosphereParameters& atmosphere, int mu_s_texels) {
  double r = 0.0, sun_sine = 0.0;
  if (!CameraAndSun(frame, &r, &sun_sine)) return false;
  const double lowest = LowestSkyCorrectionSunSine(sun_sine, atmosphere.mu_s_min, mu_s_texels);
  return SunHighWithin(r, lowest, LongestSkyRayM(r, atmosphere.bottom_radius_m, atmosphere.top_radius_m),
                       atmosphere.bottom_radius_m);
}

}  // namespace aerial
