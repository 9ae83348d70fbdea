#include "aerial/shader_abi/camera_frame_block.h"

#include <glm/gtc/type_ptr.hpp>

#include "aerial/shader_abi/frame_geometry.h"
#include "aerial/shader_abi/froxel_axes.h"

namespace aerial {
namespace {

std::array<float, 4> ToFloat4(const std::array<double, 3>& v) { return {float(v[0]), float(v[1]), float(v[2]), 0.0f}; }

}  // namespace

FrameUniforms MakeFrameUniforms(const FrameCamera& camera, double planet_radius_m, const FroxelGrid& grid) {
  glm::dmat4 view_projection = glm::make_mat4(camera.view_projection.data());
  FrameUniforms u{};
  u.view_projection = ToColumnMajorFloats(view_projection);
  u.inverse_view_projection = ToColumnMajorFloats(glm::inverse(view_projection));
  u.camera_scene_position = ToFloat4(camera.position_m);
  u.camera_planet_position =
      ToFloat4({camera.position_m[0], camera.position_m[1], camera.position_m[2] + planet_radius_m});
  u.sun_direction = ToFloat4(camera.sun_direction);
  u.froxel_size = {grid.width, grid.height, grid.depth, 0};
  u.froxel_depth = {float(grid.far_m), 0, 0, 0};
  u.viewport = {float(camera.width), float(camera.height), 0, 0};
  const FroxelAxes axes = PlaceFroxelAxes(u, planet_radius_m);
  u.froxel_rows = axes.rows.Packed();
  u.froxel_columns = axes.columns.Packed();
  return u;
}

std::array<float, 16> ToColumnMajorFloats(const glm::dmat4& m) {
  std::array<float, 16> out;
  const double* p = glm::value_ptr(m);
  for (int i = 0; i < 16; ++i) out[i] = float(p[i]);
  return out;
}

glm::dmat4 FromColumnMajorFloats(const std::array<float, 16>& m) {
  glm::dmat4 out;
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row) out[column][row] = m[column * 4 + row];
  return out;
}

glm::dvec3 ViewRayFromScreen(const FrameUniforms& frame, glm::dvec2 uv) {
  glm::dvec4 world = FromColumnMajorFloats(frame.inverse_view_projection) * glm::dvec4(uv * 2.0 - 1.0, 0.5, 1.0);
  return glm::normalize(glm::dvec3(world) / world.w);
}

}  // namespace aerial
