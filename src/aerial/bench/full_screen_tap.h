#pragma once
// A reference pass for frame benchmarks: one full-screen triangle into a radiance target of the
// frame's size whose fragments each make one trilinear 3D tap (shaders/bench/full_screen_tap.frag).
// Timed in the same run as the frames it is compared with, since its cost moves with the
// machine's load like theirs.
#include "aerial/tables.h"
#include "aerial/vk/gpu_timer.h"
#include "aerial/vk/graphics_pipeline.h"

namespace aerial::bench {

class FullScreenTap {
 public:
  // context: the bench's own, on the device of volume, any sampled 3D image (the frame's froxel
  // volume, as aerial::SceneRenderer hands it out).
  FullScreenTap(const vk::Context& context, uint32_t width, uint32_t height, const SampledImage& volume);
  // Draws the pass once, waits, and returns its GPU time (a pass named "full-screen tap").
  std::vector<PassTime> Run();

 private:
  const vk::Context& context_;
  SampledImage volume_;
  vk::Image target_;
  ::vk::raii::Sampler sampler_;
  vk::GraphicsPipeline pipeline_;
  vk::GpuTimer timer_;
};

}  // namespace aerial::bench
