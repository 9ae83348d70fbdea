#pragma once
// The per-frame froxel volume: a low-resolution grid aligned with the camera's frustum holding
// Rayleigh inscatter, Mie inscatter and transmittance from the camera to each froxel, separate and
// without phase, so that the caller's shaders apply the phase functions per pixel
// (ApplyAerialPerspective in aerial_perspective.glsl) or per vertex (GetAerialPerspectiveAtVertex).
#include <array>
#include <memory>

#include <vulkan/vulkan_core.h>

#include "aerial/device.h"
#include "aerial/froxel_grid.h"
#include "aerial/tables.h"

namespace aerial {

struct Scene;

// The camera and the sun of a frame, in the world frame of aerial/scene.h: x east, y north, z up,
// meters, the planet's center at (0, 0, -bottom_radius_m).
struct FrameCamera {
  // Camera-relative world (the camera at the origin) to Vulkan clip space, column-major. Depth
  // may be reversed or not: aerial reads distances, not depths.
  std::array<double, 16> view_projection{};
  std::array<double, 3> position_m{};
  std::array<double, 3> sun_direction{0, 0, 1};  // unit vector toward the sun
  uint32_t width = 0, height = 0;                // the viewport, in pixels
};

// The camera of a scene (aerial's infinite reversed-Z projection, no roll) for a viewport.
FrameCamera MakeFrameCamera(const Scene& scene, uint32_t width, uint32_t height);

class Froxels {
 public:
  // Throws aerial::Error for a grid outside [2, 256] per axis or a far distance <= 0.
  explicit Froxels(const Device& device, const FroxelGrid& grid = {});
  ~Froxels();
  Froxels(Froxels&&) noexcept;
  Froxels& operator=(Froxels&&) noexcept;

  // Records the frame's FrameBlock and the volume's build into the caller's command buffer
  // (outside a render pass), with barriers before (against the previous frame's reads) and after
  // (the images and the block are then readable by any later shader). Without shadows: every
  // froxel sees the sun. One Froxels per frame in flight lets frames overlap.
  void Record(VkCommandBuffer command_buffer, const Tables& tables, const FrameCamera& camera);

  const FroxelGrid& grid() const;
  // The FrameBlock of shaders/include/frame.glsl (set 0, binding 1 by the GLSL contract; its
  // C++ twin is aerial/shader_abi/frame_block.h), as the last Record filled it.
  UniformBlock frame_block() const;
  // The three 3D images (RGBA float; w unused): x and y across the screen, z in depth slices
  // (slice k's center at far_m * ((k + 0.5) / depth)^2, FroxelGrid::SliceDistance).
  SampledImage rayleigh() const;
  SampledImage mie() const;
  SampledImage transmittance() const;

  struct Impl;  // aerial's side (src/aerial/api/impl.h)

 private:
  friend struct ImplAccess;  // aerial's own code (src/aerial/api/impl.h)
  std::unique_ptr<Impl> impl_;
};

}  // namespace aerial
