#include "display_target.h"

#include <cstring>

namespace aerial::testing {

DisplayTarget::DisplayTarget(const vk::Context& context, uint32_t width, uint32_t height, ::vk::Format format)
    : context_(context),
      extent_{width, height},
      image_(context, {.extent = {width, height, 1},
                       .format = format,
                       .usage = ::vk::ImageUsageFlagBits::eColorAttachment |
                                ::vk::ImageUsageFlagBits::eTransferSrc}),
      // Left in GENERAL, the layout the readback copies from.
      render_pass_(vk::CreateColorRenderPass(context, format, ::vk::ImageLayout::eGeneral)),
      framebuffer_(vk::CreateFramebuffer(context, *render_pass_, image_.view(), extent_)) {}

std::vector<uint8_t> DisplayTarget::Draw(
    const std::function<void(const vk::CommandBuffer&)>& draw) const {
  context_.Submit([&](const vk::CommandBuffer& cmd) {
    vk::BeginRenderPass(cmd, *render_pass_, *framebuffer_, extent_);
    draw(cmd);
    cmd.endRenderPass();
    vk::FullBarrier(cmd);
  });
  std::vector<std::byte> bytes = vk::ReadImageBytes(context_, image_);
  std::vector<uint8_t> pixels(bytes.size());
  std::memcpy(pixels.data(), bytes.data(), bytes.size());
  return pixels;
}

}  // namespace aerial::testing
