#include "froxel/froxel_volume.h"

#include "aerial/shader_abi/shadow_block.h"

namespace aerial {
namespace {

// float32: the exporter writes the volume exactly as computed, and at 32^3 the size is irrelevant.
vk::ImageCreateInfo FroxelImage(const FroxelGrid& grid) {
  return {.extent = {uint32_t(grid.width), uint32_t(grid.height), uint32_t(grid.depth)},
          .volume = true};
}

// froxel.comp's constants: 0 and 1 (frame.glsl's kAerialPerPixel, unread here, and shadow.glsl's
// kSunShadows) keep their defaults; 2 is kSunHighEverywhere.
vk::ComputePipeline MakeFroxelPipeline(const vk::Context& context, FroxelPassVariant variant) {
  return vk::ComputePipeline(context, "frame/froxel.comp",
                             {{"AtmosphereBlock", vk::kUniform}, {"FrameBlock", vk::kUniform},
                              {"transmittance_texture", vk::kSampled}, {"multiple_density_texture", vk::kSampled},
                              {"rayleigh_froxels", vk::kStorageImage}, {"mie_froxels", vk::kStorageImage},
                              {"transmittance_froxels", vk::kStorageImage}, {"ShadowBlock", vk::kUniform},
                              {"shadow_map", vk::kSampled}},
                             0, {0, 1, variant == FroxelPassVariant::kSunHigh ? 1 : 0});
}

}  // namespace

FroxelVolume::FroxelVolume(const vk::Context& context, const FroxelGrid& grid)
    : grid_(grid),
      rayleigh_(context, FroxelImage(grid)),
      mie_(context, FroxelImage(grid)),
      transmittance_(context, FroxelImage(grid)),
      pipeline_(MakeFroxelPipeline(context, FroxelPassVariant::kGeneral)),
      no_shadow_block_(context, vk::UniformBufferInfo(sizeof(ShadowUniforms))),
      no_shadow_map_(context, vk::RenderTargetInfo(1, 1, vk::kDepth32f)),
      no_shadow_sampler_(vk::CreateShadowMapSampler(context)) {
  ShadowUniforms none{};  // cascades.x = 0: no shadows
  no_shadow_block_.Write(std::as_bytes(std::span(&none, 1)));
  grid.Validate();
  context.Submit([&](const auto& cmd) {
    for (const vk::Image* image : {&rayleigh_, &mie_, &transmittance_, &no_shadow_map_}) image->InitializeLayout(cmd);
  });
}

void FroxelVolume::Build(const vk::CommandBuffer& cmd, const AtmosphereTables& tables,
                         const vk::Buffer& frame_uniforms, const vk::Buffer& shadow_uniforms,
                         const vk::SampledImageSlot& shadow_map, FroxelPassVariant variant) const {
  if (variant == FroxelPassVariant::kSunHigh && !sun_high_pipeline_)
    sun_high_pipeline_.emplace(MakeFroxelPipeline(tables.context(), variant));
  const vk::ComputePipeline& pipeline = variant == FroxelPassVariant::kSunHigh ? *sun_high_pipeline_ : pipeline_;
  pipeline.Dispatch(cmd,
                     {vk::UniformBufferSlot{&tables.uniform_buffer()},
                      vk::UniformBufferSlot{&frame_uniforms},
                      tables.Sampled(tables.transmittance()),
                      tables.Sampled(tables.multiple_density()),
                      vk::StorageImageSlot{&rayleigh_}, vk::StorageImageSlot{&mie_},
                      vk::StorageImageSlot{&transmittance_}, vk::UniformBufferSlot{&shadow_uniforms},
                      shadow_map},
                     {uint32_t(grid_.width), uint32_t(grid_.height), 1}, {32, 1, 1});
}

void FroxelVolume::Build(const vk::CommandBuffer& cmd, const AtmosphereTables& tables,
                         const vk::Buffer& frame_uniforms, FroxelPassVariant variant) const {
  Build(cmd, tables, frame_uniforms, no_shadow_block_, {&no_shadow_map_, *no_shadow_sampler_}, variant);
}

FroxelTexels FroxelVolume::Read(const vk::Context& context, const FrameUniforms& frame) const {
  FroxelTexels texels{.grid = grid_, .axes = AxesOf(frame)};
  texels.rayleigh = vk::ReadImageFloats(context, rayleigh_);
  texels.mie = vk::ReadImageFloats(context, mie_);
  texels.transmittance = vk::ReadImageFloats(context, transmittance_);
  return texels;
}

}  // namespace aerial
