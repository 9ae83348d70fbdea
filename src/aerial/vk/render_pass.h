#pragma once
// A classic render pass over one color image, for passes that need a VkRenderPass rather than
// dynamic rendering: the window's (Dear ImGui 1.86's Vulkan backend draws into a render pass).
// Every pixel of the image is drawn, so its previous content is not kept.
#include "aerial/vk/context.h"

namespace aerial::vk {

// final_layout: where the image is left (PRESENT_SRC for a swapchain image).
::vk::raii::RenderPass CreateColorRenderPass(const Context& context, ::vk::Format format,
                                             ::vk::ImageLayout final_layout);
::vk::raii::Framebuffer CreateFramebuffer(const Context& context, ::vk::RenderPass render_pass,
                                          ::vk::ImageView view, ::vk::Extent2D extent);
// Begins the render pass over the whole framebuffer and sets the viewport and scissor to it.
void BeginRenderPass(const CommandBuffer& cmd, ::vk::RenderPass render_pass,
                     ::vk::Framebuffer framebuffer, ::vk::Extent2D extent);

}  // namespace aerial::vk
