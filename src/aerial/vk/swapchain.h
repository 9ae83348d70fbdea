#pragma once
// A window's swapchain as the viewer's PresentTarget (present_target.h), with several frames in
// flight: the CPU records the next frame while the GPU draws this one. The frame's commands come
// from a CommandRing; the swapchain owns the semaphores that order acquire, drawing and
// presentation.
//
// Images are 8-bit, _SRGB when the surface offers it (the format encodes the display passes'
// linear output), else UNORM (the passes encode it themselves, as for PNG files).
#include <vector>

#include "aerial/vk/present_target.h"

namespace aerial::vk {

class Swapchain : public PresentTarget {
 public:
  // surface: created by the window system for the context's instance; it must outlive this.
  // wanted: the window's framebuffer size, used when the surface does not dictate one.
  // frames_in_flight: the slots of the CommandRing the frames are recorded with.
  Swapchain(const Context& context, ::vk::SurfaceKHR surface, ::vk::Extent2D wanted,
            uint32_t frames_in_flight);
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;
  ~Swapchain() override;

  void Recreate(::vk::Extent2D wanted) override;
  bool Acquire(const CommandRing& ring) override;
  void RecordDraw(const CommandBuffer& cmd, const Recorder& draw) const override;
  void RecordCopyToBuffer(const CommandBuffer& cmd, ::vk::Buffer buffer) const override;
  // Waits for the acquire, and presents after the drawing.
  bool SubmitAndPresent(CommandRing& ring) override;

  // Whether the surface lets its images be copied out (RecordCopyToBuffer).
  bool can_copy_out() const override { return can_copy_out_; }
  ::vk::Extent2D extent() const override { return extent_; }
  ::vk::Format format() const override { return format_; }
  uint32_t min_image_count() const override { return min_image_count_; }
  uint32_t image_count() const override { return uint32_t(images_.size()); }
  ::vk::RenderPass render_pass() const override { return *render_pass_; }

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
