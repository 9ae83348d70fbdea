#include "aerial/render/sun_high_variant.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace aerial {

bool SunHighWithin(const FrameUniforms& frame, double distance_m, double bottom_radius_m) {
  const glm::dvec3 camera(frame.camera_planet_position[0], frame.camera_planet_position[1],
                          frame.camera_planet_position[2]);
  const glm::dvec3 sun(frame.sun_direction[0], frame.sun_direction[1], frame.sun_direction[2]);
  const double r = glm::length(camera), sun_length = glm::length(sun);
  if (!(r > 0.0) || !(sun_length > 0.0) || !(bottom_radius_m > 0.0) || !(distance_m >= 0.0)) return false;
  const double sun_elevation = std::asin(std::clamp(glm::dot(camera / r, sun / sun_length), -1.0, 1.0));
  // A point d from the camera, both at least R from the planet's centre (the marches stop at the
  // ground), sees the centre at an angle theta from the camera with sin theta <= d / R (law of
  // sines), and its horizontal is turned by theta: the sun's elevation there is at least the
  // camera's minus theta.
  const double nearest_radius = std::min(r, bottom_radius_m);
  const double arc = std::asin(std::min(distance_m / nearest_radius, 1.0));
  return std::sin(sun_elevation - arc) > kSunDiscOneTapSine + 0.005;
}

}  // namespace aerial
