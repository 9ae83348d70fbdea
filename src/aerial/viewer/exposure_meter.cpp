#include "aerial/viewer/exposure_meter.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "aerial/image/exposure.h"

namespace aerial::viewer {
namespace {

struct MeterPush {
  float luminance_weights[4];
  float limits[4];
};

}  // namespace

ExposureMeter::ExposureMeter(const vk::Context& context, uint32_t frames_in_flight)
    : pipeline_(context, "view/meter.comp", {{"radiance_image", vk::kSampled}, {"Meter", vk::kStorageBuffer}},
                sizeof(MeterPush)),
      nearest_(vk::CreateNearestClampSampler(context)),
      pending_(frames_in_flight, false) {
  for (uint32_t slot = 0; slot < frames_in_flight; ++slot)
    results_.emplace_back(context, vk::BufferCreateInfo{.size = sizeof(float),
                                                        .usage = ::vk::BufferUsageFlagBits::eStorageBuffer,
                                                        .host_visible = true});
}

void ExposureMeter::Record(const vk::CommandBuffer& cmd, uint32_t slot, const SampledImage& radiance) {
  MeterPush push{
      {float(kLuminancePerChannel[0]), float(kLuminancePerChannel[1]), float(kLuminancePerChannel[2]), 0.0f},
      {float(kMinLuminance), float(kMeteredLowFraction), float(kMeteredHighFraction), 0.0f}};
  vk::FullBarrier(cmd);  // after the frame's passes wrote the radiance
  pipeline_.Dispatch(cmd, {vk::SampledViewSlot{radiance.view, *nearest_}, vk::StorageBufferSlot{&results_[slot]}},
                     {16, 16, 1}, {16, 16, 1}, &push);
  vk::FullBarrier(cmd);  // before the host reads the result
  pending_[slot] = true;
}

std::optional<double> ExposureMeter::TakeAverageLuminance(uint32_t slot) {
  if (!pending_[slot]) return std::nullopt;
  pending_[slot] = false;
  float mean_log = 0.0f;
  std::memcpy(&mean_log, results_[slot].mapped(), sizeof mean_log);
  if (!std::isfinite(mean_log)) return std::nullopt;
  return std::exp(double(mean_log));
}

double AdaptEv100(double current, double target, double dt_s, double time_constant_s) {
  return target + (current - target) * std::exp(-std::max(dt_s, 0.0) / time_constant_s);
}

}  // namespace aerial::viewer
