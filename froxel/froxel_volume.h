#pragma once
// The per-frame froxel volume on the GPU: three 3D images (Rayleigh inscatter, Mie inscatter,
// transmittance; phase-free) filled by shaders/frame/froxel.comp from the precomputed tables,
// single scattering shadowed through the sun's shadow map.
#include <optional>

#include "aerial/froxel_grid.h"
#include "aerial/precompute/atmosphere_tables.h"
#include "aerial/vk/compute_pipeline.h"
#include "froxel/froxel_pass_variant.h"
#include "froxel/froxel_placement.h"

namespace aerial {

class FroxelVolume {
 public:
  FroxelVolume(const vk::Context& context, const FroxelGrid& grid);

  // Records the froxel pass. frame_uniforms: the FrameBlock buffer of this frame; shadow_uniforms
  // and shadow_map: the ShadowBlock and the depth atlas of shaders/include/shadow.glsl. variant:
  // ChooseFroxelPassVariant of the block's values (kSunHigh only where it allows it); its
  // pipeline is made at its first use.
  void Build(const vk::CommandBuffer& cmd, const AtmosphereTables& tables,
             const vk::Buffer& frame_uniforms, const vk::Buffer& shadow_uniforms,
             const vk::SampledImageSlot& shadow_map, FroxelPassVariant variant) const;
  // The same without the sun's shadows (every visibility 1), for a caller with no shadow map: a
  // renderer that embeds aerial and fills the FrameBlock for its own camera (docs/api.md).
  void Build(const vk::CommandBuffer& cmd, const AtmosphereTables& tables, const vk::Buffer& frame_uniforms,
             FroxelPassVariant variant) const;

  const FroxelGrid& grid() const { return grid_; }
  const vk::Image& rayleigh() const { return rayleigh_; }
  const vk::Image& mie() const { return mie_; }
  const vk::Image& transmittance() const { return transmittance_; }

  // Copies the three images back as computed (RGBA float texels), with the rows of `frame`, the
  // FrameBlock that built them. Call after the frame that built them has finished
  // (Renderer::Render waits for it).
  FroxelTexels Read(const vk::Context& context, const FrameUniforms& frame) const;

 private:
  FroxelGrid grid_;
  vk::Image rayleigh_, mie_, transmittance_;
  vk::ComputePipeline pipeline_;  // kGeneral
  mutable std::optional<vk::ComputePipeline> sun_high_pipeline_;
  // What the shadowless Build binds for the shadow map: a ShadowBlock with no cascades (so the
  // shader never reads the map) and a one-texel depth map with its comparing sampler.
  vk::Buffer no_shadow_block_;
  vk::Image no_shadow_map_;
  ::vk::raii::Sampler no_shadow_sampler_;
};

}  // namespace aerial
