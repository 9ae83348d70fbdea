#pragma once
// The viewer's last passes, drawn straight into the window's image inside its render pass: the
// renderer's frame tone mapped, or a debug view of it (shaders/include/display.glsl). Each is one
// full-screen triangle whose fragment shader writes every pixel; nothing is copied. They only
// read the renderer's images, as aerial's public API hands them out (aerial/renderer.h): the
// frame itself is always SceneRenderer::Record's, as in
// `aerial render`.
#include <array>

#include "aerial/renderer.h"
#include "aerial/vk/graphics_pipeline.h"

namespace aerial::viewer {

class DisplayPasses {
 public:
  // render_pass: any render pass with one color attachment of the target's format (the
  // swapchain's); the passes are recorded inside it, or inside a compatible one. An _SRGB format
  // encodes sRGB itself; with a UNORM one the shaders encode.
  DisplayPasses(const vk::Context& context, ::vk::RenderPass render_pass, ::vk::Format format);

  // Each records one draw over a target of `extent` inside the caller's render pass.
  // The picture: radiance times the white balance's gains and the exposure through the PNGs'
  // curve, sRGB encoding and dither (shaders/view/present.frag), resampled bilinearly to the target.
  void RecordToneMap(const vk::CommandBuffer& cmd, ::vk::Extent2D extent, const SampledImage& radiance,
                     float exposure, const std::array<float, 3>& white_balance = {1.0f, 1.0f, 1.0f}) const;

  enum class Term { kRayleigh = 0, kMie = 1, kTransmittance = 2 };
  // One term of the aerial perspective alone (shaders/view/inscatter.frag), for the renderer's
  // frame recorded with the per-frame resources of `slot`.
  void RecordTerm(const vk::CommandBuffer& cmd, ::vk::Extent2D extent,
                  const SceneRenderer& renderer, uint32_t slot, Term term, float exposure) const;
  // Depth slice `slice` of the renderer's froxel volume (shaders/view/froxel_slice.frag).
  void RecordFroxelSlice(const vk::CommandBuffer& cmd, ::vk::Extent2D extent,
                         const SceneRenderer& renderer, int slice, float exposure) const;
  // The 3D-vs-4D relative difference as a heat map, white at full_scale
  // (shaders/view/difference.frag).
  void RecordDifference(const vk::CommandBuffer& cmd, ::vk::Extent2D extent,
                        const SampledImage& radiance_4d, const SampledImage& radiance_3d,
                        float full_scale) const;

 private:
  // One of aerial's images with this pass's linear sampler.
  vk::SampledViewSlot Linear(const SampledImage& image) const { return {image.view, *linear_}; }

  ::vk::raii::Sampler linear_, nearest_;
  // The picture of a frame of the target's size, read texel for texel, and of another size.
  vk::GraphicsPipeline tone_map_, tone_map_resampled_, term_, froxel_slice_, difference_;
};

}  // namespace aerial::viewer
