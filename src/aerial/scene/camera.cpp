#include "aerial/scene/camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/gtc/type_ptr.hpp>

#include "aerial/froxels.h"

namespace aerial {
namespace {
double Radians(double degrees) { return degrees * std::numbers::pi / 180.0; }
}  // namespace

glm::dvec3 DirectionFromZenithAzimuth(double zenith_deg, double azimuth_deg) {
  double zenith = Radians(zenith_deg), azimuth = Radians(azimuth_deg);
  return {std::sin(zenith) * std::sin(azimuth), std::sin(zenith) * std::cos(azimuth),
          std::cos(zenith)};
}

glm::dvec3 Sun::Direction() const { return DirectionFromZenithAzimuth(zenith_deg, azimuth_deg); }

glm::dvec3 Forward(const Camera& camera) {
  return DirectionFromZenithAzimuth(90.0 - camera.pitch_deg, camera.yaw_deg);
}

glm::dvec3 Right(const Camera& camera) {
  double yaw = Radians(camera.yaw_deg);
  return {std::cos(yaw), -std::sin(yaw), 0.0};
}

glm::dvec3 Up(const Camera& camera) { return glm::cross(Right(camera), Forward(camera)); }

glm::dmat4 ViewMatrix(const Camera& camera) {
  glm::dvec3 right = Right(camera), up = Up(camera), back = -Forward(camera);
  glm::dmat4 view(1.0);  // glm is column-major: view[column][row]
  for (int i = 0; i < 3; ++i) {
    view[i][0] = right[i];
    view[i][1] = up[i];
    view[i][2] = back[i];
  }
  view[3][0] = -glm::dot(right, camera.position);
  view[3][1] = -glm::dot(up, camera.position);
  view[3][2] = -glm::dot(back, camera.position);
  return view;
}

glm::dmat4 ProjectionMatrix(const Camera& camera, double aspect) {
  double f = 1.0 / std::tan(Radians(camera.vertical_fov_deg) / 2.0);
  glm::dmat4 projection(0.0);
  projection[0][0] = f / aspect;
  projection[1][1] = -f;
  projection[3][2] = camera.near_m;  // clip.z = near
  projection[2][3] = -1.0;           // clip.w = -z_view
  return projection;
}

FrameCamera MakeFrameCamera(const Scene& scene, uint32_t width, uint32_t height) {
  // Shaders see camera-relative positions, so the view matrix drops the camera's translation.
  Camera at_origin = scene.camera;
  at_origin.position = glm::dvec3(0.0);
  glm::dmat4 projection = ProjectionMatrix(scene.camera, double(width) / double(height));
  // clip.w = -z_view, so these terms subtract themselves from x_ndc and y_ndc, which span 2 over
  // the frame's width and height: the image moves by -jitter_px pixels.
  projection[2][0] = 2.0 * scene.camera.jitter_px.x / double(width);
  projection[2][1] = 2.0 * scene.camera.jitter_px.y / double(height);
  glm::dmat4 view_projection = projection * ViewMatrix(at_origin);
  FrameCamera camera{.width = width, .height = height};
  std::copy_n(glm::value_ptr(view_projection), 16, camera.view_projection.begin());
  glm::dvec3 sun = scene.sun.Direction();
  camera.position_m = {scene.camera.position.x, scene.camera.position.y, scene.camera.position.z};
  camera.sun_direction = {sun.x, sun.y, sun.z};
  return camera;
}

std::vector<glm::dvec2> SupersampleJitters(int n) {
  std::vector<glm::dvec2> jitters;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) jitters.push_back({(x + 0.5) / n - 0.5, (y + 0.5) / n - 0.5});
  return jitters;
}

}  // namespace aerial
