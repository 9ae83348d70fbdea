#pragma once
// The frame's uniform block as the shaders see it (FrameBlock in shaders/include/frame.glsl), and
// the CPU twins of what the shaders compute from it. It sits below render/ and froxel/, which
// both use it: the renderer fills it (render/frame_uniforms.h), the froxel placement reads it.
// tests/uniform_layout_test.cpp checks it member by member against the GLSL compiler's layout.
#include <array>

#include <glm/glm.hpp>

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

// The view ray through the screen point uv ((0, 0) top-left), as frame.glsl computes it.
glm::dvec3 ViewRayFromScreen(const FrameUniforms& frame, glm::dvec2 uv);

std::array<float, 16> ToColumnMajorFloats(const glm::dmat4& m);

}  // namespace aerial
