#pragma once
// A window's swapchain and how aerial draws into it: each frame acquires an image, draws it in one
// render pass (the display pass writes every pixel, then an overlay such as Dear ImGui goes on
// top), and presents it, with several frames in flight: the CPU records the next frame while the
// GPU draws this one. The frame's commands come from a CommandRing; the swapchain owns the
// semaphores that order acquire, drawing and presentation.
//
// Images are 8-bit, _SRGB when the surface offers it (the format encodes the display passes'
// linear output), else UNORM (the passes encode it themselves, as for PNG files).
#include <functional>
#include <vector>

#include "aerial/vk/command_ring.h"
#include "aerial/vk/resources.h"

namespace aerial::vk {

using Recorder = std::function<void(const CommandBuffer&)>;

// Whether a format sRGB-encodes what is stored to it (the _SRGB ones aerial uses).
bool EncodesSrgb(::vk::Format format);

class Swapchain {
 public:
  // surface: created by the window system for the context's instance; it must outlive this.
  // wanted: the window's framebuffer size, used when the surface does not dictate one.
  // frames_in_flight: the slots of the CommandRing the frames are recorded with.
  Swapchain(const Context& context, ::vk::SurfaceKHR surface, ::vk::Extent2D wanted,
            uint32_t frames_in_flight);
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;
  ~Swapchain();

  // Rebuilds the images for a new size (after a resize, or when Acquire or Present returned
  // false). Waits for the device to be idle first.
  void Recreate(::vk::Extent2D wanted);

  // Acquires the next image for the ring's current slot (after CommandRing::Begin). False when
  // the swapchain is out of date: Recreate, and record nothing for this frame.
  bool Acquire(const CommandRing& ring);
  // Records the render pass over the acquired image: `draw` must write every pixel.
  void RecordDraw(const CommandBuffer& cmd, const Recorder& draw) const;
  // Records a copy of the drawn image (after RecordDraw) into buffer, which holds
  // extent().width * height 4-byte texels of format(), row by row. Only where can_copy_out().
  void RecordCopyToBuffer(const CommandBuffer& cmd, ::vk::Buffer buffer) const;
  // Submits the ring's command buffer (waiting for the acquire) and presents the image. False
  // when the swapchain is out of date or suboptimal: Recreate.
  bool SubmitAndPresent(CommandRing& ring);

  // Whether the surface lets its images be copied out (RecordCopyToBuffer).
  bool can_copy_out() const { return can_copy_out_; }
  ::vk::Extent2D extent() const { return extent_; }
  ::vk::Format format() const { return format_; }
  uint32_t min_image_count() const { return min_image_count_; }
  uint32_t image_count() const { return uint32_t(images_.size()); }
  ::vk::RenderPass render_pass() const { return *render_pass_; }

 private:
  void Create(::vk::Extent2D wanted);

  const Context& context_;
  ::vk::SurfaceKHR surface_;
  ::vk::Format format_ = ::vk::Format::eUndefined;
  ::vk::PresentModeKHR present_mode_ = ::vk::PresentModeKHR::eFifo;
  ::vk::Extent2D extent_;
  uint32_t min_image_count_ = 2;
  ::vk::raii::RenderPass render_pass_{nullptr};
  ::vk::raii::SwapchainKHR swapchain_{nullptr};
  std::vector<::vk::Image> images_;
  std::vector<::vk::raii::ImageView> views_;
  std::vector<::vk::raii::Framebuffer> framebuffers_;
  // Per image, since a semaphore waited on by a present may still be in use until that image is
  // acquired again.
  std::vector<::vk::raii::Semaphore> rendered_;
  // Per ring slot: reused once the slot's previous frame, which waited on it, has finished.
  std::vector<::vk::raii::Semaphore> acquired_;
  uint32_t image_ = 0;
  bool suboptimal_ = false;
  bool can_copy_out_ = false;
};

}  // namespace aerial::vk
