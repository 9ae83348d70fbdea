#include "aerial/render/frame_uniforms.h"

#include "aerial/scene/camera.h"

namespace aerial {
namespace {

std::array<float, 4> ToFloat4(const glm::dvec3& v) { return {float(v.x), float(v.y), float(v.z), 0.0f}; }

}  // namespace

FrameUniforms MakeFrameUniforms(const Scene& scene, double planet_radius_m, int width, int height,
                                const FroxelGrid& froxels) {
  // Shaders see camera-relative positions, so the view matrix drops the camera's translation.
  Camera at_origin = scene.camera;
  at_origin.position = glm::dvec3(0.0);
  glm::dmat4 view_projection =
      ProjectionMatrix(scene.camera, double(width) / double(height)) * ViewMatrix(at_origin);
  FrameUniforms u{};
  u.view_projection = ToColumnMajorFloats(view_projection);
  u.inverse_view_projection = ToColumnMajorFloats(glm::inverse(view_projection));
  u.camera_scene_position = ToFloat4(scene.camera.position);
  // The planet's center is at (0, 0, -R) in the scene frame.
  u.camera_planet_position = ToFloat4(scene.camera.position + glm::dvec3(0.0, 0.0, planet_radius_m));
  u.sun_direction = ToFloat4(scene.sun.Direction());
  u.froxel_size = {froxels.width, froxels.height, froxels.depth, 0};
  u.froxel_depth = {float(froxels.far_m), 0, 0, 0};
  u.viewport = {float(width), float(height), 0, 0};
  return u;
}

}  // namespace aerial
