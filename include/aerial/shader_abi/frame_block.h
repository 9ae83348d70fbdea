#pragma once
// The frame's uniform block as the shaders see it (FrameBlock in shaders/include/frame.glsl).
// aerial fills it (src/aerial/shader_abi/camera_frame_block.h); the froxel placement reads it
// (froxel/froxel_placement.h). tests/uniform_layout_test.cpp checks it member by member against
// the GLSL compiler's layout.
#include <array>

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
  std::array<float, 4> froxel_rows;               // the rows' placement (froxel_axes.glsl)
  std::array<float, 4> froxel_columns;            // the columns' placement
};
static_assert(sizeof(FrameUniforms) == 2 * 64 + 8 * 16);

}  // namespace aerial
