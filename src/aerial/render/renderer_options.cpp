#include "aerial/render/renderer_options.h"

namespace aerial {

FrameMemory EstimateFrameMemory(const RendererOptions& options) {
  FrameMemory memory = EstimateFrameMemory(static_cast<const RenderOptions&>(options));
  if (options.terrain != TerrainMode::kLod) memory.terrain = 0;
  // The surfaces' radiance that the froxels' full-screen pass reads: rgba32f at the render size.
  if (options.mode == AerialMode::kFroxel && options.surface_froxel_reads == SurfaceFroxelReads::kFullScreenPass)
    memory.targets += uint64_t(options.render_width()) * options.render_height() * 16;
  return memory;
}

}  // namespace aerial
