#include "aerial/render/renderer_options.h"

namespace aerial {

FrameMemory EstimateFrameMemory(const RendererOptions& options) {
  FrameMemory memory = EstimateFrameMemory(static_cast<const RenderOptions&>(options));
  if (options.terrain != TerrainMode::kLod) memory.terrain = 0;
  return memory;
}

}  // namespace aerial
