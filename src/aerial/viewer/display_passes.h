#pragma once
// The viewer's last passes before the swapchain: the renderer's frame, or a debug view of it, into
// the 8-bit display image that the swapchain copies from (vk/swapchain.h). They only read the
// renderer's images: the frame itself is always Renderer::Render's, as in `aerial render`.
#include "aerial/render/renderer.h"
#include "aerial/vk/compute_pipeline.h"

namespace aerial::viewer {

// The swapchain's format if compute shaders can write it, else R8G8B8A8_UNORM (which every device
// can, and which the swapchain then converts when it blits).
::vk::Format DisplayFormat(const vk::Context& context, ::vk::Format swapchain_format);

class DisplayPasses {
 public:
  // format: of the display image, an 8-bit UNORM format the device can store to. The swapchain's
  // own format (DisplayFormat) makes the swapchain's blit a plain copy.
  DisplayPasses(const vk::Context& context, uint32_t width, uint32_t height,
                ::vk::Format format = ::vk::Format::eR8G8B8A8Unorm);

  // Recreates the display image for a new size (nothing may be in flight).
  void Resize(uint32_t width, uint32_t height);
  // sRGB-encoded values, GENERAL layout.
  const vk::Image& display() const { return *display_; }

  // The picture: radiance times exposure through ACES and sRGB (shaders/view/present.comp).
  void RecordToneMap(const ::vk::raii::CommandBuffer& cmd, const vk::Image& radiance,
                     float exposure) const;

  enum class Term { kRayleigh = 0, kMie = 1, kTransmittance = 2 };
  // One term of the aerial perspective alone (shaders/view/inscatter.comp). Writes the renderer's
  // frame uniforms into a buffer of this pass, so record it after the renderer's Render.
  void RecordTerm(const ::vk::raii::CommandBuffer& cmd, const Renderer& renderer, Term term,
                  float exposure);
  // Depth slice `slice` of the froxel volume (shaders/view/froxel_slice.comp).
  void RecordFroxelSlice(const ::vk::raii::CommandBuffer& cmd, const FroxelVolume& froxels,
                         int slice, float exposure) const;
  // The 3D-vs-4D relative difference as a heat map, white at full_scale
  // (shaders/view/difference.comp).
  void RecordDifference(const ::vk::raii::CommandBuffer& cmd, const vk::Image& radiance_4d,
                        const vk::Image& radiance_3d, float full_scale) const;

 private:
  void Dispatch(const ::vk::raii::CommandBuffer& cmd, const vk::ComputePipeline& pipeline,
                std::vector<vk::Slot> slots, const void* push_constants) const;

  const vk::Context& context_;
  ::vk::Format format_;
  ::vk::raii::Sampler sampler_;
  std::unique_ptr<vk::Image> display_;
  vk::Buffer frame_buffer_;
  vk::ComputePipeline tone_map_, term_, froxel_slice_, difference_;
};

}  // namespace aerial::viewer
