#pragma once
// Where one frame's froxels sit in the world, on the CPU, from the same FrameBlock the shaders
// read (aerial/shader_abi/frame_block.h), and the CPU twin of the shaders' trilinear read.
//
// Froxel (i, j, k) stands for the point at distance grid.SliceDistance(k + 0.5) along the unit
// view ray through the screen position uv = (columns.ScreenPosition((i + 0.5) / W),
// rows.ScreenPosition((j + 0.5) / H)) (the frame's columns and rows, froxel_axes.h), the ray being
// normalize(inverse_view_projection * (2 uv - 1, 0.5, 1)) as in shaders/include/frame.glsl
// (ViewRayFromScreen). uv (0, 0) is the top-left of the image (Vulkan clip y points down), so j
// grows downward. The slices are therefore spherical shells around the camera, not planes.
#include <array>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "aerial/froxel_grid.h"
#include "aerial/shader_abi/frame_geometry.h"
#include "aerial/shader_abi/froxel_axes.h"

namespace aerial {

class FroxelPlacement {
 public:
  FroxelPlacement(const FrameUniforms& frame, const FroxelGrid& grid);

  const FroxelGrid& grid() const { return grid_; }
  glm::dvec3 camera_position() const { return camera_; }

  // Unit ray (world frame) through a screen position, uv in [0, 1]^2.
  glm::dvec3 RayThroughScreen(glm::dvec2 uv) const;
  // World position (scene frame, m) of the center of froxel (i, j, k).
  glm::dvec3 FroxelCenter(int i, int j, int k) const;

  // The inverse: a world position's screen position uv and distance from the camera, or nothing
  // if it lies behind the camera. uv may fall outside [0, 1]^2 (outside the frustum).
  struct ScreenPoint {
    glm::dvec2 uv;
    double distance;
  };
  std::optional<ScreenPoint> ToScreen(const glm::dvec3& world) const;
  // Whether a screen point lies inside the volume the froxels cover: on screen and no farther
  // than far_m.
  bool Covers(const ScreenPoint& point) const;

  // The axis-aligned world box around the covered volume (camera apex and far cap).
  std::array<glm::dvec3, 2> Bounds() const;

 private:
  FrameUniforms frame_;
  glm::dmat4 view_projection_;
  glm::dvec3 camera_;
  FroxelGrid grid_;
  FroxelAxes axes_;
};

// The three froxel images read back (RGBA float texels, x fastest, then y, then z), and a CPU
// read that mirrors SampleFroxels in shaders/include/froxel.glsl: trilinear with clamp-to-edge
// at the screen position's froxel coordinates (axes), blended toward the empty segment below the
// first slice center.
struct FroxelTexels {
  FroxelGrid grid;
  FroxelAxes axes;  // of the frame that computed them
  std::vector<float> rayleigh, mie, transmittance;  // 4 floats per texel

  struct Sample {
    glm::dvec3 rayleigh, mie, transmittance;
  };
  Sample Read(glm::dvec2 uv, double distance) const;
};

}  // namespace aerial
