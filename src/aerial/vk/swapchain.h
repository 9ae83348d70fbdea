#pragma once
// A window's swapchain and the one way aerial presents: a finished image (a compute pass's output
// in GENERAL layout) is copied into the swapchain image, an overlay is drawn over it inside a
// render pass, and the image is presented. The render pass exists for the overlay: Dear ImGui
// 1.86's Vulkan backend draws into a VkRenderPass (it predates dynamic rendering).
//
// Images are 8-bit UNORM: aerial encodes sRGB in its own shaders, exactly as it does for PNG files,
// so an sRGB swapchain format would encode twice. One frame is in flight: Present waits for the
// frame's fence, which is what the synchronous renderer does anyway.
#include <functional>
#include <vector>

#include "aerial/vk/resources.h"

namespace aerial::vk {

using Recorder = std::function<void(const ::vk::raii::CommandBuffer&)>;

class Swapchain {
 public:
  // surface: created by the window system for the context's instance; it must outlive this.
  // wanted: the window's framebuffer size, used when the surface does not dictate one.
  Swapchain(const Context& context, ::vk::SurfaceKHR surface, ::vk::Extent2D wanted);
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;
  ~Swapchain();

  // Rebuilds the images for a new size (after a resize, or when Present returned false). Waits for
  // the device to be idle first.
  void Recreate(::vk::Extent2D wanted);

  // One frame: acquires an image, records `prepare` (the passes that fill `source`), copies `source`
  // (GENERAL layout, the swapchain's extent; in format(), or in any blittable color format, then
  // converted by a blit) into the image, records `overlay` inside the render pass, submits, waits,
  // presents. Returns false when the swapchain is out of date or suboptimal and nothing (or a
  // possibly stretched image) was shown: Recreate.
  bool Present(const Image& source, const Recorder& prepare, const Recorder& overlay);

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
  ::vk::raii::Semaphore acquired_{nullptr};
  ::vk::raii::Fence frame_done_{nullptr};
  ::vk::raii::CommandPool command_pool_{nullptr};
  ::vk::raii::CommandBuffer command_buffer_{nullptr};
};

}  // namespace aerial::vk
