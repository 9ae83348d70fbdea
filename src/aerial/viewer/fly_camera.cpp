#include "aerial/viewer/fly_camera.h"

#include <algorithm>
#include <cmath>

#include "aerial/scene/camera.h"

namespace aerial::viewer {

void Fly(Camera& camera, const FlyInput& input, double dt_s, double planet_radius_m,
         const FlySpeeds& speeds) {
  camera.yaw_deg = std::fmod(camera.yaw_deg + input.look_dx_px * speeds.degrees_per_pixel, 360.0);
  if (camera.yaw_deg < 0.0) camera.yaw_deg += 360.0;
  camera.pitch_deg =
      std::clamp(camera.pitch_deg - input.look_dy_px * speeds.degrees_per_pixel, -89.0, 89.0);

  double speed = speeds.meters_per_second * (input.fast ? 10.0 : 1.0) * (input.slow ? 0.1 : 1.0);
  glm::dvec3 step = input.forward * Forward(camera) + input.right * Right(camera) +
                    input.up * glm::dvec3(0.0, 0.0, 1.0);
  camera.position += step * (speed * dt_s);

  // Altitude above the sphere centered at (0, 0, -R) (scene.h), clamped along the radius.
  const glm::dvec3 center(0.0, 0.0, -planet_radius_m);
  glm::dvec3 radial = camera.position - center;
  double r = glm::length(radial);
  double clamped = std::clamp(r, planet_radius_m - 500.0, planet_radius_m + 100e3);
  if (clamped != r) camera.position = center + radial * (clamped / r);
}

}  // namespace aerial::viewer
