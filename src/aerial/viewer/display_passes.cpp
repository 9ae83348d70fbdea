#include "aerial/viewer/display_passes.h"

namespace aerial::viewer {
namespace {

using vk::kSampled;
using vk::kStorageImage;
using vk::kUniform;

std::unique_ptr<vk::Image> MakeDisplay(const vk::Context& context, uint32_t width, uint32_t height,
                                       ::vk::Format format) {
  auto image = std::make_unique<vk::Image>(
      context, vk::ImageCreateInfo{.extent = {width, height, 1},
                                   .format = format,
                                   .usage = ::vk::ImageUsageFlagBits::eStorage |
                                            ::vk::ImageUsageFlagBits::eTransferSrc});
  context.Submit([&](const auto& cmd) { image->InitializeLayout(cmd); });
  return image;
}

struct TermPush {
  int32_t term;
  int32_t from_froxels;
  float exposure;
};

struct SlicePush {
  int32_t slice;
  float exposure;
};

}  // namespace

::vk::Format DisplayFormat(const vk::Context& context, ::vk::Format swapchain_format) {
  auto features = context.physical_device().getFormatProperties(swapchain_format).optimalTilingFeatures;
  return features & ::vk::FormatFeatureFlagBits::eStorageImage ? swapchain_format
                                                                : ::vk::Format::eR8G8B8A8Unorm;
}

DisplayPasses::DisplayPasses(const vk::Context& context, uint32_t width, uint32_t height,
                             ::vk::Format format)
    : context_(context),
      format_(format),
      sampler_(vk::CreateLinearClampSampler(context)),
      display_(MakeDisplay(context, width, height, format)),
      frame_buffer_(context, {.size = sizeof(FrameUniforms),
                              .usage = ::vk::BufferUsageFlagBits::eUniformBuffer,
                              .host_visible = true}),
      tone_map_(context, "view/present.comp", {kSampled, kStorageImage}, sizeof(float)),
      term_(context, "view/inscatter.comp",
            {kUniform, kUniform, kSampled, kSampled, kSampled, kSampled, kSampled, kSampled,
             kSampled, kSampled, kStorageImage},
            sizeof(TermPush)),
      froxel_slice_(context, "view/froxel_slice.comp",
                    {kSampled, kSampled, kSampled, kStorageImage}, sizeof(SlicePush)),
      difference_(context, "view/difference.comp", {kSampled, kSampled, kStorageImage},
                  sizeof(float)) {}

void DisplayPasses::Resize(uint32_t width, uint32_t height) {
  display_ = MakeDisplay(context_, width, height, format_);
}

void DisplayPasses::Dispatch(const ::vk::raii::CommandBuffer& cmd,
                             const vk::ComputePipeline& pipeline, std::vector<vk::Slot> slots,
                             const void* push_constants) const {
  slots.push_back(vk::StorageImageSlot{display_.get()});
  ::vk::Extent3D extent = display_->extent();
  pipeline.Dispatch(cmd, slots, {extent.width, extent.height, 1}, {8, 8, 1}, push_constants);
}

void DisplayPasses::RecordToneMap(const ::vk::raii::CommandBuffer& cmd, const vk::Image& radiance,
                                  float exposure) const {
  Dispatch(cmd, tone_map_, {vk::SampledImageSlot{&radiance, *sampler_}}, &exposure);
}

void DisplayPasses::RecordTerm(const ::vk::raii::CommandBuffer& cmd, const Renderer& renderer,
                               Term term, float exposure) {
  const FrameUniforms& uniforms = renderer.frame_uniforms();
  frame_buffer_.Write(std::as_bytes(std::span(&uniforms, 1)));
  const AtmosphereTables& tables = renderer.tables();
  const FroxelVolume& froxels = renderer.froxels();
  auto sampled = [&](const vk::Image& image) { return vk::SampledImageSlot{&image, *sampler_}; };
  TermPush push{int32_t(term), renderer.options().mode == AerialMode::kFroxel ? 1 : 0, exposure};
  Dispatch(cmd, term_,
           {vk::UniformBufferSlot{&tables.uniform_buffer()}, vk::UniformBufferSlot{&frame_buffer_},
            sampled(tables.transmittance()), sampled(tables.rayleigh()), sampled(tables.mie()),
            sampled(tables.multiple()), sampled(froxels.rayleigh()), sampled(froxels.mie()),
            sampled(froxels.transmittance()), sampled(renderer.surface_image())},
           &push);
}

void DisplayPasses::RecordFroxelSlice(const ::vk::raii::CommandBuffer& cmd,
                                      const FroxelVolume& froxels, int slice,
                                      float exposure) const {
  SlicePush push{slice, exposure};
  Dispatch(cmd, froxel_slice_,
           {vk::SampledImageSlot{&froxels.rayleigh(), *sampler_},
            vk::SampledImageSlot{&froxels.mie(), *sampler_},
            vk::SampledImageSlot{&froxels.transmittance(), *sampler_}},
           &push);
}

void DisplayPasses::RecordDifference(const ::vk::raii::CommandBuffer& cmd,
                                     const vk::Image& radiance_4d, const vk::Image& radiance_3d,
                                     float full_scale) const {
  Dispatch(cmd, difference_,
           {vk::SampledImageSlot{&radiance_4d, *sampler_}, vk::SampledImageSlot{&radiance_3d, *sampler_}},
           &full_scale);
}

}  // namespace aerial::viewer
