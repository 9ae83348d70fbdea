#include "aerial/vk/render_pass.h"

#include "aerial/vk/graphics_pipeline.h"

namespace aerial::vk {

::vk::raii::RenderPass CreateColorRenderPass(const Context& context, ::vk::Format format,
                                             ::vk::ImageLayout final_layout) {
  ::vk::AttachmentDescription attachment{.format = format,
                                         .samples = ::vk::SampleCountFlagBits::e1,
                                         .loadOp = ::vk::AttachmentLoadOp::eDontCare,
                                         .storeOp = ::vk::AttachmentStoreOp::eStore,
                                         .stencilLoadOp = ::vk::AttachmentLoadOp::eDontCare,
                                         .stencilStoreOp = ::vk::AttachmentStoreOp::eDontCare,
                                         .initialLayout = ::vk::ImageLayout::eUndefined,
                                         .finalLayout = final_layout};
  ::vk::AttachmentReference color{.attachment = 0, .layout = ::vk::ImageLayout::eColorAttachmentOptimal};
  ::vk::SubpassDescription subpass{.pipelineBindPoint = ::vk::PipelineBindPoint::eGraphics,
                                   .colorAttachmentCount = 1,
                                   .pColorAttachments = &color};
  // The layout transition waits for the image to be ready for writing: a swapchain image's
  // acquire semaphore is waited on at the color output stage.
  ::vk::SubpassDependency before{.srcSubpass = VK_SUBPASS_EXTERNAL,
                                 .dstSubpass = 0,
                                 .srcStageMask = ::vk::PipelineStageFlagBits::eColorAttachmentOutput,
                                 .dstStageMask = ::vk::PipelineStageFlagBits::eColorAttachmentOutput,
                                 .srcAccessMask = {},
                                 .dstAccessMask = ::vk::AccessFlagBits::eColorAttachmentWrite};
  return ::vk::raii::RenderPass(context.device(),
                                ::vk::RenderPassCreateInfo{.attachmentCount = 1,
                                                           .pAttachments = &attachment,
                                                           .subpassCount = 1,
                                                           .pSubpasses = &subpass,
                                                           .dependencyCount = 1,
                                                           .pDependencies = &before});
}

::vk::raii::Framebuffer CreateFramebuffer(const Context& context, ::vk::RenderPass render_pass,
                                          ::vk::ImageView view, ::vk::Extent2D extent) {
  return ::vk::raii::Framebuffer(context.device(),
                                 ::vk::FramebufferCreateInfo{.renderPass = render_pass,
                                                             .attachmentCount = 1,
                                                             .pAttachments = &view,
                                                             .width = extent.width,
                                                             .height = extent.height,
                                                             .layers = 1});
}

void BeginRenderPass(const CommandBuffer& cmd, ::vk::RenderPass render_pass,
                     ::vk::Framebuffer framebuffer, ::vk::Extent2D extent) {
  cmd.beginRenderPass(::vk::RenderPassBeginInfo{.renderPass = render_pass,
                                                .framebuffer = framebuffer,
                                                .renderArea = {.extent = extent}},
                      ::vk::SubpassContents::eInline);
  SetViewport(cmd, extent);
}

}  // namespace aerial::vk
