#include "aerial/viewer/frame_accumulator.h"

namespace aerial::viewer {
namespace {

constexpr uint32_t kLocalSize = 8;  // accumulate.comp's workgroup side

}  // namespace

AccumulationStep NextAccumulationStep(int frames_averaged) {
  return {kAccumulationJitters[size_t(frames_averaged) % kAccumulationJitters.size()],
          1.0f / float(frames_averaged + 1)};
}

FrameAccumulator::FrameAccumulator(const vk::Context& context)
    : context_(context),
      pipeline_(context, "view/accumulate.comp",
                {{"radiance_image", vk::kSampled}, {"average_image", vk::kStorageImage}}, sizeof(float)),
      nearest_(vk::CreateNearestClampSampler(context)) {}

bool FrameAccumulator::Fits(VkExtent3D extent) const {
  return mean_ && mean_->extent().width == extent.width && mean_->extent().height == extent.height;
}

void FrameAccumulator::Resize(VkExtent3D extent) {
  frames_ = 0;
  mean_.reset();
  mean_.emplace(context_, vk::ImageCreateInfo{.extent = {extent.width, extent.height, 1}});
  context_.Submit([&](const vk::CommandBuffer& cmd) { mean_->InitializeLayout(cmd); });
}

void FrameAccumulator::Record(const vk::CommandBuffer& cmd, const SampledImage& frame) {
  const float weight = NextAccumulationStep(frames_).weight;
  vk::FullBarrier(cmd);  // after the frame's passes wrote it, and after the last display read the mean
  pipeline_.Dispatch(cmd, {vk::SampledViewSlot{frame.view, *nearest_}, vk::StorageImageSlot{&*mean_}},
                     mean_->extent(), {kLocalSize, kLocalSize, 1}, &weight);
  vk::FullBarrier(cmd);  // before the display pass reads it
  ++frames_;
}

SampledImage FrameAccumulator::mean() const {
  return {.image = mean_->handle(),
          .view = mean_->view(),
          .sampler = *nearest_,
          .layout = VK_IMAGE_LAYOUT_GENERAL,
          .format = VkFormat(mean_->format()),
          .extent = mean_->extent()};
}

ImageRgbF FrameAccumulator::Read() const {
  return ImageRgbF{int(mean_->extent().width), int(mean_->extent().height), vk::ReadImageFloats(context_, *mean_)};
}

}  // namespace aerial::viewer
