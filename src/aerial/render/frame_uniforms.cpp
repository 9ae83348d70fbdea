#include "aerial/render/frame_uniforms.h"

namespace aerial {

FrameUniforms MakeFrameUniforms(const Scene& scene, double planet_radius_m, int width, int height,
                                const FroxelGrid& froxels) {
  return MakeFrameUniforms(MakeFrameCamera(scene, uint32_t(width), uint32_t(height)), planet_radius_m, froxels);
}

}  // namespace aerial
