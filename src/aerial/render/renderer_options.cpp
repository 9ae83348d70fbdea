#include "aerial/render/renderer_options.h"

namespace aerial {

bool AerialPerspectiveInFullScreenPass(const RendererOptions& options) {
  if (options.mode == AerialMode::kFroxel) return options.surface_froxel_reads == SurfaceFroxelReads::kFullScreenPass;
  return options.per_pixel_in_full_screen_pass;
}

FrameMemory EstimateFrameMemory(const RendererOptions& options) {
  FrameMemory memory = EstimateFrameMemory(static_cast<const RenderOptions&>(options));
  if (options.terrain != TerrainMode::kLod) memory.terrain = 0;
  else if (options.terrain_selector == TerrainSelector::kCpu) memory.terrain -= GpuTerrainSelectionBytes(options);
  // The surfaces' radiance that the full-screen pass reads, rgba32f at the render size, which the
  // public estimate counts for the per-pixel modes (they take that pass by default).
  const uint64_t surface_radiance = uint64_t(options.render_width()) * options.render_height() * 16;
  const bool counted = options.mode != AerialMode::kFroxel;
  if (AerialPerspectiveInFullScreenPass(options) && !counted) memory.targets += surface_radiance;
  if (!AerialPerspectiveInFullScreenPass(options) && counted) memory.targets -= surface_radiance;
  return memory;
}

}  // namespace aerial
