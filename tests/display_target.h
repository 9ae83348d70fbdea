#pragma once
// An offscreen stand-in for the viewer's window: an 8-bit image with a render pass like the
// swapchain's, so tests record the viewer's display passes exactly as the viewer does and read
// back what the window would show.
#include <functional>
#include <vector>

#include "aerial/vk/render_pass.h"
#include "aerial/vk/resources.h"

namespace aerial::testing {

class DisplayTarget {
 public:
  DisplayTarget(const vk::Context& context, uint32_t width, uint32_t height,
                ::vk::Format format = ::vk::Format::eR8G8B8A8Unorm);

  ::vk::RenderPass render_pass() const { return *render_pass_; }
  ::vk::Extent2D extent() const { return extent_; }
  // Records draw inside the render pass over the image, submits, waits, and returns the bytes.
  std::vector<uint8_t> Draw(const std::function<void(const vk::CommandBuffer&)>& draw) const;

 private:
  const vk::Context& context_;
  ::vk::Extent2D extent_;
  vk::Image image_;
  ::vk::raii::RenderPass render_pass_;
  ::vk::raii::Framebuffer framebuffer_;
};

}  // namespace aerial::testing
