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
  float highlight_weights[4];  // xyz: the white balance's gains times kRadiancePerNmToLuminance
};

struct MeterResult {
  float mean_log_luminance;
  float log_highlight;
};

}  // namespace

ExposureMeter::ExposureMeter(const vk::Context& context, uint32_t frames_in_flight)
    : pipeline_(context, "view/meter.comp", {{"radiance_image", vk::kSampled}, {"Meter", vk::kStorageBuffer}},
                sizeof(MeterPush)),
      nearest_(vk::CreateNearestClampSampler(context)),
      pending_(frames_in_flight, false) {
  for (uint32_t slot = 0; slot < frames_in_flight; ++slot)
    results_.emplace_back(context, vk::BufferCreateInfo{.size = sizeof(MeterResult),
                                                        .usage = ::vk::BufferUsageFlagBits::eStorageBuffer,
                                                        .host_visible = true});
}

void ExposureMeter::Record(const vk::CommandBuffer& cmd, uint32_t slot, const SampledImage& radiance,
                           const std::array<double, 3>& white_balance) {
  MeterPush push{
      {float(kLuminancePerChannel[0]), float(kLuminancePerChannel[1]), float(kLuminancePerChannel[2]), 0.0f},
      {float(kMinLuminance), float(kMeteredLowFraction), float(kMeteredHighFraction), float(kHighlightFraction)},
      {float(kRadiancePerNmToLuminance * white_balance[0]), float(kRadiancePerNmToLuminance * white_balance[1]),
       float(kRadiancePerNmToLuminance * white_balance[2]), 0.0f}};
  vk::FullBarrier(cmd);  // after the frame's passes wrote the radiance
  pipeline_.Dispatch(cmd, {vk::SampledViewSlot{radiance.view, *nearest_}, vk::StorageBufferSlot{&results_[slot]}},
                     {16, 16, 1}, {16, 16, 1}, &push);
  vk::FullBarrier(cmd);  // before the host reads the result
  pending_[slot] = true;
}

std::optional<MeterReading> ExposureMeter::TakeReading(uint32_t slot) {
  if (!pending_[slot]) return std::nullopt;
  pending_[slot] = false;
  MeterResult result;
  std::memcpy(&result, results_[slot].mapped(), sizeof result);
  if (!std::isfinite(result.mean_log_luminance) || !std::isfinite(result.log_highlight)) return std::nullopt;
  return MeterReading{.average_luminance = std::exp(double(result.mean_log_luminance)),
                      .highlight = std::exp(double(result.log_highlight))};
}

double AdaptEv100(double current, double target, double dt_s, double time_constant_s) {
  return target + (current - target) * std::exp(-std::max(dt_s, 0.0) / time_constant_s);
}

}  // namespace aerial::viewer
