#include "aerial/vk/swapchain.h"

#include <algorithm>

#include "aerial/error.h"
#include "aerial/vk/render_pass.h"

namespace aerial::vk {
namespace {

// An 8-bit format the surface offers with the sRGB colour space and that can be drawn to: an
// _SRGB one (the format encodes) if there is one, else UNORM (the shaders encode).
::vk::Format ChooseFormat(const Context& context, ::vk::SurfaceKHR surface) {
  auto formats = context.physical_device().getSurfaceFormatsKHR(surface);
  for (::vk::Format wanted : {::vk::Format::eB8G8R8A8Srgb, ::vk::Format::eR8G8B8A8Srgb,
                              ::vk::Format::eB8G8R8A8Unorm, ::vk::Format::eR8G8B8A8Unorm}) {
    bool offered = std::any_of(formats.begin(), formats.end(), [&](const auto& f) {
      return f.format == wanted && f.colorSpace == ::vk::ColorSpaceKHR::eSrgbNonlinear;
    });
    auto features = context.physical_device().getFormatProperties(wanted).optimalTilingFeatures;
    if (offered && (features & ::vk::FormatFeatureFlagBits::eColorAttachment)) return wanted;
  }
  std::string offered;
  for (const auto& f : formats) offered += (offered.empty() ? "" : ", ") + ::vk::to_string(f.format);
  throw Error("swapchain format", offered, "B8G8R8A8 or R8G8B8A8, SRGB or UNORM, renderable");
}

// Mailbox shows the newest frame without tearing and without waiting for vertical blank, so frame
// times measure the renderer; FIFO (always available) otherwise.
::vk::PresentModeKHR ChoosePresentMode(const Context& context, ::vk::SurfaceKHR surface) {
  auto modes = context.physical_device().getSurfacePresentModesKHR(surface);
  bool mailbox = std::find(modes.begin(), modes.end(), ::vk::PresentModeKHR::eMailbox) != modes.end();
  return mailbox ? ::vk::PresentModeKHR::eMailbox : ::vk::PresentModeKHR::eFifo;
}

}  // namespace

bool EncodesSrgb(::vk::Format format) {
  return format == ::vk::Format::eB8G8R8A8Srgb || format == ::vk::Format::eR8G8B8A8Srgb;
}

Swapchain::Swapchain(const Context& context, ::vk::SurfaceKHR surface, ::vk::Extent2D wanted,
                     uint32_t frames_in_flight)
    : context_(context),
      surface_(surface),
      format_(ChooseFormat(context, surface)),
      present_mode_(ChoosePresentMode(context, surface)),
      render_pass_(CreateColorRenderPass(context, format_, ::vk::ImageLayout::ePresentSrcKHR)) {
  for (uint32_t i = 0; i < frames_in_flight; ++i)
    acquired_.emplace_back(context.device(), ::vk::SemaphoreCreateInfo{});
  Create(wanted);
}

Swapchain::~Swapchain() { context_.device().waitIdle(); }

void Swapchain::Recreate(::vk::Extent2D wanted) {
  context_.device().waitIdle();
  Create(wanted);
}

void Swapchain::Create(::vk::Extent2D wanted) {
  auto caps = context_.physical_device().getSurfaceCapabilitiesKHR(surface_);
  if (!(caps.supportedUsageFlags & ::vk::ImageUsageFlagBits::eColorAttachment))
    throw Error("swapchain image usage", ::vk::to_string(caps.supportedUsageFlags), "color attachment");
  // Copies out of the images take the window's picture, panel and all (RecordCopyToBuffer). Only
  // color attachment is guaranteed by the specification, so the copy is asked for where offered.
  can_copy_out_ = bool(caps.supportedUsageFlags & ::vk::ImageUsageFlagBits::eTransferSrc);
  const ::vk::ImageUsageFlags usage =
      ::vk::ImageUsageFlagBits::eColorAttachment |
      (can_copy_out_ ? ::vk::ImageUsageFlagBits::eTransferSrc : ::vk::ImageUsageFlags{});
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
                                                  .subresourceRange = {
                                                      .aspectMask = ::vk::ImageAspectFlagBits::eColor,
                                                      .levelCount = 1,
                                                      .layerCount = 1}});
    framebuffers_.push_back(CreateFramebuffer(context_, *render_pass_, *views_.back(), extent_));
    rendered_.emplace_back(context_.device(), ::vk::SemaphoreCreateInfo{});
  }
}

bool Swapchain::Acquire(const CommandRing& ring) {
  try {
    auto [result, index] = swapchain_.acquireNextImage(UINT64_MAX, *acquired_[ring.slot()]);
    image_ = index;
    suboptimal_ = result != ::vk::Result::eSuccess;
    return true;
  } catch (const ::vk::OutOfDateKHRError&) {
    return false;
  }
}

void Swapchain::RecordDraw(const CommandBuffer& cmd, const Recorder& draw) const {
  BeginRenderPass(cmd, *render_pass_, *framebuffers_[image_], extent_);
  draw(cmd);
  cmd.endRenderPass();
}

void Swapchain::RecordCopyToBuffer(const CommandBuffer& cmd, ::vk::Buffer buffer) const {
  const ::vk::ImageSubresourceRange color{.aspectMask = ::vk::ImageAspectFlagBits::eColor, .levelCount = 1, .layerCount = 1};
  auto transition = [&](::vk::ImageLayout from, ::vk::ImageLayout to, ::vk::AccessFlags src, ::vk::AccessFlags dst,
                        ::vk::PipelineStageFlags src_stage, ::vk::PipelineStageFlags dst_stage) {
    cmd.pipelineBarrier(src_stage, dst_stage, {}, {}, {},
                        ::vk::ImageMemoryBarrier{.srcAccessMask = src, .dstAccessMask = dst, .oldLayout = from,
                                                 .newLayout = to, .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                                 .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                                 .image = images_[image_], .subresourceRange = color});
  };
  transition(::vk::ImageLayout::ePresentSrcKHR, ::vk::ImageLayout::eTransferSrcOptimal,
             ::vk::AccessFlagBits::eColorAttachmentWrite, ::vk::AccessFlagBits::eTransferRead,
             ::vk::PipelineStageFlagBits::eColorAttachmentOutput, ::vk::PipelineStageFlagBits::eTransfer);
  RecordCopyToHostBuffer(cmd, images_[image_], ::vk::ImageLayout::eTransferSrcOptimal, extent_, buffer);
  transition(::vk::ImageLayout::eTransferSrcOptimal, ::vk::ImageLayout::ePresentSrcKHR, ::vk::AccessFlagBits::eTransferRead,
             {}, ::vk::PipelineStageFlagBits::eTransfer, ::vk::PipelineStageFlagBits::eBottomOfPipe);
}

bool Swapchain::SubmitAndPresent(CommandRing& ring) {
  ::vk::Semaphore wait = *acquired_[ring.slot()], signal = *rendered_[image_];
  ::vk::PipelineStageFlags stage = ::vk::PipelineStageFlagBits::eColorAttachmentOutput;
  ring.Submit(std::span(&wait, 1), std::span(&stage, 1), std::span(&signal, 1));
  ::vk::SwapchainKHR swapchain = *swapchain_;
  try {
    ::vk::Result presented = context_.queue().presentKHR(::vk::PresentInfoKHR{
        .waitSemaphoreCount = 1, .pWaitSemaphores = &signal, .swapchainCount = 1,
        .pSwapchains = &swapchain, .pImageIndices = &image_});
    return !suboptimal_ && presented == ::vk::Result::eSuccess;
  } catch (const ::vk::OutOfDateKHRError&) {
    return false;
  }
}

}  // namespace aerial::vk
