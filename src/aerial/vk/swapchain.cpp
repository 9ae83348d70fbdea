#include "aerial/vk/swapchain.h"

#include <algorithm>

#include "aerial/core/error.h"

namespace aerial::vk {
namespace {

// An 8-bit UNORM format the surface offers with the sRGB colour space (see the header for why not
// an _SRGB format), and that blits can write.
::vk::Format ChooseFormat(const Context& context, ::vk::SurfaceKHR surface) {
  auto formats = context.physical_device().getSurfaceFormatsKHR(surface);
  for (::vk::Format wanted : {::vk::Format::eB8G8R8A8Unorm, ::vk::Format::eR8G8B8A8Unorm}) {
    bool offered = std::any_of(formats.begin(), formats.end(), [&](const auto& f) {
      return f.format == wanted && f.colorSpace == ::vk::ColorSpaceKHR::eSrgbNonlinear;
    });
    auto features = context.physical_device().getFormatProperties(wanted).optimalTilingFeatures;
    if (offered && (features & ::vk::FormatFeatureFlagBits::eBlitDst)) return wanted;
  }
  std::string offered;
  for (const auto& f : formats) offered += (offered.empty() ? "" : ", ") + ::vk::to_string(f.format);
  throw Error("swapchain format", offered, "B8G8R8A8_UNORM or R8G8B8A8_UNORM, blittable");
}

// Mailbox shows the newest frame without tearing and without waiting for vertical blank, so frame
// times measure the renderer; FIFO (always available) otherwise.
::vk::PresentModeKHR ChoosePresentMode(const Context& context, ::vk::SurfaceKHR surface) {
  auto modes = context.physical_device().getSurfacePresentModesKHR(surface);
  bool mailbox = std::find(modes.begin(), modes.end(), ::vk::PresentModeKHR::eMailbox) != modes.end();
  return mailbox ? ::vk::PresentModeKHR::eMailbox : ::vk::PresentModeKHR::eFifo;
}

// Loads the blitted image, leaves it ready to present.
::vk::raii::RenderPass CreateOverlayRenderPass(const Context& context, ::vk::Format format) {
  ::vk::AttachmentDescription attachment{.format = format,
                                         .samples = ::vk::SampleCountFlagBits::e1,
                                         .loadOp = ::vk::AttachmentLoadOp::eLoad,
                                         .storeOp = ::vk::AttachmentStoreOp::eStore,
                                         .stencilLoadOp = ::vk::AttachmentLoadOp::eDontCare,
                                         .stencilStoreOp = ::vk::AttachmentStoreOp::eDontCare,
                                         .initialLayout = ::vk::ImageLayout::eTransferDstOptimal,
                                         .finalLayout = ::vk::ImageLayout::ePresentSrcKHR};
  ::vk::AttachmentReference color{.attachment = 0, .layout = ::vk::ImageLayout::eColorAttachmentOptimal};
  ::vk::SubpassDescription subpass{.pipelineBindPoint = ::vk::PipelineBindPoint::eGraphics,
                                   .colorAttachmentCount = 1,
                                   .pColorAttachments = &color};
  // The blit's writes before the overlay's reads and writes of the same image.
  ::vk::SubpassDependency after_blit{
      .srcSubpass = VK_SUBPASS_EXTERNAL,
      .dstSubpass = 0,
      .srcStageMask = ::vk::PipelineStageFlagBits::eTransfer,
      .dstStageMask = ::vk::PipelineStageFlagBits::eColorAttachmentOutput,
      .srcAccessMask = ::vk::AccessFlagBits::eTransferWrite,
      .dstAccessMask = ::vk::AccessFlagBits::eColorAttachmentRead |
                       ::vk::AccessFlagBits::eColorAttachmentWrite};
  return ::vk::raii::RenderPass(context.device(),
                                ::vk::RenderPassCreateInfo{.attachmentCount = 1,
                                                           .pAttachments = &attachment,
                                                           .subpassCount = 1,
                                                           .pSubpasses = &subpass,
                                                           .dependencyCount = 1,
                                                           .pDependencies = &after_blit});
}

::vk::ImageSubresourceRange ColorRange() {
  return {.aspectMask = ::vk::ImageAspectFlagBits::eColor, .levelCount = 1, .layerCount = 1};
}

}  // namespace

Swapchain::Swapchain(const Context& context, ::vk::SurfaceKHR surface, ::vk::Extent2D wanted)
    : context_(context),
      surface_(surface),
      format_(ChooseFormat(context, surface)),
      present_mode_(ChoosePresentMode(context, surface)),
      render_pass_(CreateOverlayRenderPass(context, format_)),
      acquired_(context.device(), ::vk::SemaphoreCreateInfo{}),
      frame_done_(context.device(), ::vk::FenceCreateInfo{}),
      command_pool_(context.device(),
                    ::vk::CommandPoolCreateInfo{
                        .flags = ::vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                        .queueFamilyIndex = context.queue_family()}) {
  command_buffer_ = std::move(::vk::raii::CommandBuffers(
      context.device(), ::vk::CommandBufferAllocateInfo{.commandPool = *command_pool_,
                                                        .level = ::vk::CommandBufferLevel::ePrimary,
                                                        .commandBufferCount = 1})
                                  .front());
  Create(wanted);
}

Swapchain::~Swapchain() { context_.device().waitIdle(); }

void Swapchain::Recreate(::vk::Extent2D wanted) {
  context_.device().waitIdle();
  Create(wanted);
}

void Swapchain::Create(::vk::Extent2D wanted) {
  auto caps = context_.physical_device().getSurfaceCapabilitiesKHR(surface_);
  const auto usage = ::vk::ImageUsageFlagBits::eColorAttachment | ::vk::ImageUsageFlagBits::eTransferDst;
  if ((caps.supportedUsageFlags & usage) != usage)
    throw Error("swapchain image usage", ::vk::to_string(caps.supportedUsageFlags),
                "color attachment and transfer destination");
  // 0xFFFFFFFF: the surface takes the swapchain's size (Vulkan spec, VkSurfaceCapabilitiesKHR).
  extent_ = caps.currentExtent.width != 0xFFFFFFFFu
                ? caps.currentExtent
                : ::vk::Extent2D{
                      std::clamp(wanted.width, caps.minImageExtent.width, caps.maxImageExtent.width),
                      std::clamp(wanted.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
  if (extent_.width == 0 || extent_.height == 0)
    throw Error("swapchain extent", "0x0", "a window that is not minimized");
  // One more than the minimum, so acquiring does not wait for the presentation engine.
  min_image_count_ = std::max(caps.minImageCount, 2u);
  uint32_t count = min_image_count_ + 1;
  if (caps.maxImageCount > 0) count = std::min(count, caps.maxImageCount);

  framebuffers_.clear();
  views_.clear();
  ::vk::SwapchainKHR old = *swapchain_;
  swapchain_ = ::vk::raii::SwapchainKHR(
      context_.device(),
      ::vk::SwapchainCreateInfoKHR{.surface = surface_,
                                   .minImageCount = count,
                                   .imageFormat = format_,
                                   .imageColorSpace = ::vk::ColorSpaceKHR::eSrgbNonlinear,
                                   .imageExtent = extent_,
                                   .imageArrayLayers = 1,
                                   .imageUsage = usage,
                                   .imageSharingMode = ::vk::SharingMode::eExclusive,
                                   .preTransform = caps.currentTransform,
                                   .compositeAlpha = ::vk::CompositeAlphaFlagBitsKHR::eOpaque,
                                   .presentMode = present_mode_,
                                   .clipped = VK_TRUE,
                                   .oldSwapchain = old});
  images_ = swapchain_.getImages();
  rendered_.clear();
  for (::vk::Image image : images_) {
    views_.emplace_back(context_.device(),
                        ::vk::ImageViewCreateInfo{.image = image,
                                                  .viewType = ::vk::ImageViewType::e2D,
                                                  .format = format_,
                                                  .subresourceRange = ColorRange()});
    ::vk::ImageView view = *views_.back();
    framebuffers_.emplace_back(context_.device(),
                               ::vk::FramebufferCreateInfo{.renderPass = *render_pass_,
                                                           .attachmentCount = 1,
                                                           .pAttachments = &view,
                                                           .width = extent_.width,
                                                           .height = extent_.height,
                                                           .layers = 1});
    rendered_.emplace_back(context_.device(), ::vk::SemaphoreCreateInfo{});
  }
}

bool Swapchain::Present(const Image& source, const Recorder& prepare, const Recorder& overlay) {
  uint32_t index = 0;
  bool current = true;
  try {
    auto [result, acquired] = swapchain_.acquireNextImage(UINT64_MAX, *acquired_);
    index = acquired;
    current = result == ::vk::Result::eSuccess;
  } catch (const ::vk::OutOfDateKHRError&) {
    return false;
  }
  const auto& cmd = command_buffer_;
  cmd.reset();
  cmd.begin(::vk::CommandBufferBeginInfo{.flags = ::vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
  prepare(cmd);
  FullBarrier(cmd);
  // The acquire semaphore is waited on at the transfer stage; the transition chains to it.
  ::vk::ImageMemoryBarrier to_transfer{.srcAccessMask = {},
                                       .dstAccessMask = ::vk::AccessFlagBits::eTransferWrite,
                                       .oldLayout = ::vk::ImageLayout::eUndefined,
                                       .newLayout = ::vk::ImageLayout::eTransferDstOptimal,
                                       .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                       .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                       .image = images_[index],
                                       .subresourceRange = ColorRange()};
  cmd.pipelineBarrier(::vk::PipelineStageFlagBits::eTransfer, ::vk::PipelineStageFlagBits::eTransfer,
                      {}, {}, {}, to_transfer);
  // A copy when the formats match (a memcpy on a CPU device), else a blit, which converts.
  ::vk::ImageSubresourceLayers layer{.aspectMask = ::vk::ImageAspectFlagBits::eColor, .layerCount = 1};
  if (source.format() == format_) {
    cmd.copyImage(source.handle(), ::vk::ImageLayout::eGeneral, images_[index],
                  ::vk::ImageLayout::eTransferDstOptimal,
                  ::vk::ImageCopy{.srcSubresource = layer, .dstSubresource = layer,
                                  .extent = {extent_.width, extent_.height, 1}});
  } else {
    std::array<::vk::Offset3D, 2> corners = {
        ::vk::Offset3D{0, 0, 0}, ::vk::Offset3D{int32_t(extent_.width), int32_t(extent_.height), 1}};
    cmd.blitImage(source.handle(), ::vk::ImageLayout::eGeneral, images_[index],
                  ::vk::ImageLayout::eTransferDstOptimal,
                  ::vk::ImageBlit{.srcSubresource = layer, .srcOffsets = corners,
                                  .dstSubresource = layer, .dstOffsets = corners},
                  ::vk::Filter::eNearest);
  }
  cmd.beginRenderPass(::vk::RenderPassBeginInfo{.renderPass = *render_pass_,
                                                .framebuffer = *framebuffers_[index],
                                                .renderArea = {.extent = extent_}},
                      ::vk::SubpassContents::eInline);
  overlay(cmd);
  cmd.endRenderPass();
  cmd.end();

  context_.device().resetFences(*frame_done_);
  ::vk::PipelineStageFlags wait_stage = ::vk::PipelineStageFlagBits::eTransfer;
  ::vk::CommandBuffer raw = *cmd;
  ::vk::Semaphore wait = *acquired_, signal = *rendered_[index];
  context_.queue().submit(::vk::SubmitInfo{.waitSemaphoreCount = 1,
                                           .pWaitSemaphores = &wait,
                                           .pWaitDstStageMask = &wait_stage,
                                           .commandBufferCount = 1,
                                           .pCommandBuffers = &raw,
                                           .signalSemaphoreCount = 1,
                                           .pSignalSemaphores = &signal},
                          *frame_done_);
  if (context_.device().waitForFences(*frame_done_, VK_TRUE, UINT64_MAX) != ::vk::Result::eSuccess)
    throw Error("vkWaitForFences", "timeout", "completion");
  ::vk::SwapchainKHR swapchain = *swapchain_;
  try {
    ::vk::Result presented = context_.queue().presentKHR(::vk::PresentInfoKHR{
        .waitSemaphoreCount = 1, .pWaitSemaphores = &signal, .swapchainCount = 1,
        .pSwapchains = &swapchain, .pImageIndices = &index});
    return current && presented == ::vk::Result::eSuccess;
  } catch (const ::vk::OutOfDateKHRError&) {
    return false;
  }
}

}  // namespace aerial::vk
