#pragma once
// The std140 per-frame block of shaders/include/frame.glsl (FrameBlock): camera, sun, froxel grid.
#include <array>

#include "aerial/scene/scene.h"
#include "froxel/froxel_grid.h"

namespace aerial {

enum class AerialMode { kFroxel, kPerPixel };

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

// The unit view ray (camera-relative world) through screen point uv in [0, 1]^2: the CPU twin of
// ViewRayFromScreen in shaders/include/frame.glsl, in double precision.
glm::dvec3 ViewRayFromScreen(const FrameUniforms& frame, glm::dvec2 uv);

// A matrix as std140 stores a mat4: column-major floats.
std::array<float, 16> ToColumnMajorFloats(const glm::dmat4& m);

FrameUniforms MakeFrameUniforms(const Scene& scene, double planet_radius_m, int width, int height,
                                const FroxelGrid& froxels);

}  // namespace aerial
