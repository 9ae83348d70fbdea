#pragma once
// The frame's uniform block as the shaders see it (FrameBlock in shaders/include/frame.glsl), and
// how a camera fills it. It sits below render/ and froxel/, which both use it: the renderer
// fills it (render/frame_uniforms.h), the froxel placement reads it (froxel/froxel_placement.h).
// tests/uniform_layout_test.cpp checks it member by member against the GLSL compiler's layout.
#include <array>

#include "aerial/froxel_grid.h"
#include "aerial/froxels.h"

namespace aerial {

struct alignas(16) FrameUniforms {
  std::array<float, 16> view_projection;          // column-major, camera-relative world -> clip
  std::array<float, 16> inverse_view_projection;
  std::array<float, 4> camera_scene_position;
  std::array<float, 4> camera_planet_position;
  std::array<float, 4> sun_direction;
  std::array<int, 4> froxel_size;                 // w unused (the mode is a specialization constant)
  std::array<float, 4> froxel_depth;              // x: far distance
  std::array<float, 4> viewport;
};
static_assert(sizeof(FrameUniforms) == 2 * 64 + 6 * 16);

// The block for a camera (aerial/froxels.h) on a planet of radius planet_radius_m, with a froxel
// grid. Shaders see camera-relative positions; the planet's center is at (0, 0, -R).
FrameUniforms MakeFrameUniforms(const FrameCamera& camera, double planet_radius_m, const FroxelGrid& grid);

}  // namespace aerial
