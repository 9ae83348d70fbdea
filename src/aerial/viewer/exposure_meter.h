#pragma once
// The viewer's automatic exposure: a meter on the GPU (shaders/view/meter.comp) that takes the
// reading of each frame (ReadMeter, aerial/image/exposure.h) into a small buffer per frame in flight, read once that
// frame has finished, and an adaptation that moves the exposure toward it over time, as an eye
// or a camera does, rather than jumping with every frame.
#include <optional>
#include <vector>

#include "aerial/image/exposure.h"
#include "aerial/renderer.h"
#include "aerial/vk/compute_pipeline.h"
#include "aerial/vk/resources.h"

namespace aerial::viewer {

class ExposureMeter {
 public:
  ExposureMeter(const vk::Context& context, uint32_t frames_in_flight);

  // Records the metering of `radiance`, to be shown with these white balance gains, for the frame
  // in `slot` (outside any render pass).
  void Record(const vk::CommandBuffer& cmd, uint32_t slot, const SampledImage& radiance,
              const std::array<double, 3>& white_balance);
  // What the slot's finished frame metered; none if the slot has not metered since it was last
  // read.
  std::optional<MeterReading> TakeReading(uint32_t slot);

 private:
  vk::ComputePipeline pipeline_;
  ::vk::raii::Sampler nearest_;
  std::vector<vk::Buffer> results_;
  std::vector<bool> pending_;
};

// The EV100 after dt_s seconds of adapting from `current` toward `target`: exponential, with a
// time constant of time_constant_s (Frostbite's and Unreal's adaptation; 1 s by default).
double AdaptEv100(double current, double target, double dt_s, double time_constant_s = 1.0);

}  // namespace aerial::viewer
