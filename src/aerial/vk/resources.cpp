#include "aerial/vk/resources.h"

#include <cstring>
#include <optional>

#include "aerial/error.h"

namespace aerial::vk {
namespace {

::vk::raii::DeviceMemory Allocate(const Context& context, ::vk::MemoryRequirements requirements,
                                  ::vk::MemoryPropertyFlags properties) {
  return ::vk::raii::DeviceMemory(
      context.device(),
      ::vk::MemoryAllocateInfo{
          .allocationSize = requirements.size,
          .memoryTypeIndex = context.FindMemoryType(requirements.memoryTypeBits, properties)});
}

::vk::ImageAspectFlags AspectOf(::vk::Format format) {
  return format == ::vk::Format::eD32Sfloat ? ::vk::ImageAspectFlagBits::eDepth
                                            : ::vk::ImageAspectFlagBits::eColor;
}

::vk::ImageSubresourceRange WholeRange(::vk::Format format) {
  return {.aspectMask = AspectOf(format), .levelCount = 1, .layerCount = 1};
}

}  // namespace

Buffer::Buffer(const Context& context, const BufferCreateInfo& info)
    : buffer_(context.device(), ::vk::BufferCreateInfo{.size = info.size, .usage = info.usage}),
      size_(info.size) {
  auto properties = info.host_visible ? ::vk::MemoryPropertyFlagBits::eHostVisible |
                                            ::vk::MemoryPropertyFlagBits::eHostCoherent
                                      : ::vk::MemoryPropertyFlagBits::eDeviceLocal;
  memory_ = Allocate(context, buffer_.getMemoryRequirements(), properties);
  buffer_.bindMemory(*memory_, 0);
  if (info.host_visible) mapped_ = static_cast<std::byte*>(memory_.mapMemory(0, info.size));
}

void Buffer::Write(std::span<const std::byte> bytes, ::vk::DeviceSize offset) {
  if (!mapped_ || offset + bytes.size() > size_)
    throw Error("buffer write", std::to_string(bytes.size()) + " bytes",
                "a host-visible buffer of at least " + std::to_string(offset + bytes.size()));
  std::memcpy(mapped_ + offset, bytes.data(), bytes.size());
}

void Buffer::RecordUpdate(const CommandBuffer& cmd, std::span<const std::byte> bytes) const {
  // vkCmdUpdateBuffer's limits (Vulkan spec, VUID-vkCmdUpdateBuffer-dataSize-00037/00038).
  if (bytes.size() > 65536 || bytes.size() % 4 != 0 || bytes.size() > size_)
    throw Error("recorded buffer update", std::to_string(bytes.size()) + " bytes",
                "a multiple of 4, at most 65536 and at most the buffer's " + std::to_string(size_));
  FullBarrier(cmd);
  cmd.updateBuffer(*buffer_, 0, ::vk::ArrayProxy<const std::byte>(uint32_t(bytes.size()), bytes.data()));
  FullBarrier(cmd);
}

Image::Image(const Context& context, const ImageCreateInfo& info)
    : image_(context.device(),
             ::vk::ImageCreateInfo{.imageType = info.extent.depth > 1 || info.volume
                                                    ? ::vk::ImageType::e3D
                                                    : ::vk::ImageType::e2D,
                                   .format = info.format,
                                   .extent = info.extent,
                                   .mipLevels = 1,
                                   .arrayLayers = 1,
                                   .samples = ::vk::SampleCountFlagBits::e1,
                                   .tiling = ::vk::ImageTiling::eOptimal,
                                   .usage = info.usage,
                                   .initialLayout = ::vk::ImageLayout::eUndefined}),
      extent_(info.extent),
      format_(info.format),
      volume_(info.extent.depth > 1 || info.volume) {
  memory_ = Allocate(context, image_.getMemoryRequirements(),
                     ::vk::MemoryPropertyFlagBits::eDeviceLocal);
  image_.bindMemory(*memory_, 0);
  view_ = ::vk::raii::ImageView(
      context.device(),
      ::vk::ImageViewCreateInfo{.image = *image_,
                                .viewType = is_3d() ? ::vk::ImageViewType::e3D
                                                    : ::vk::ImageViewType::e2D,
                                .format = info.format,
                                .subresourceRange = WholeRange(info.format)});
}

size_t Image::texel_bytes() const {
  switch (format_) {
    case ::vk::Format::eR32G32B32A32Sfloat: return 16;
    case ::vk::Format::eR16G16B16A16Sfloat: return 8;
    case ::vk::Format::eR8G8B8A8Unorm:
    case ::vk::Format::eR8G8B8A8Srgb:
    case ::vk::Format::eB8G8R8A8Unorm:
    case ::vk::Format::eB8G8R8A8Srgb:
    case ::vk::Format::eR32Sfloat:
    case ::vk::Format::eD32Sfloat: return 4;
    default: throw Error("image format", ::vk::to_string(format_), "a format aerial knows the size of");
  }
}

size_t Image::byte_size() const {
  return texel_bytes() * extent_.width * extent_.height * extent_.depth;
}

void Image::InitializeLayout(const CommandBuffer& cmd) const {
  ::vk::ImageMemoryBarrier barrier{.srcAccessMask = {},
                                   .dstAccessMask = ::vk::AccessFlagBits::eMemoryRead |
                                                    ::vk::AccessFlagBits::eMemoryWrite,
                                   .oldLayout = ::vk::ImageLayout::eUndefined,
                                   .newLayout = ::vk::ImageLayout::eGeneral,
                                   .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                   .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                   .image = *image_,
                                   .subresourceRange = WholeRange(format_)};
  cmd.pipelineBarrier(::vk::PipelineStageFlagBits::eTopOfPipe,
                      ::vk::PipelineStageFlagBits::eAllCommands, {}, {}, {}, barrier);
}

void Image::Clear(const CommandBuffer& cmd) const {
  cmd.clearColorImage(*image_, ::vk::ImageLayout::eGeneral,
                      ::vk::ClearColorValue{.float32 = std::array<float, 4>{0, 0, 0, 0}}, WholeRange(format_));
}

namespace {
::vk::BufferImageCopy WholeImageCopy(::vk::Extent3D extent, ::vk::Format format) {
  return ::vk::BufferImageCopy{.imageSubresource = {.aspectMask = AspectOf(format), .layerCount = 1},
                               .imageExtent = extent};
}
}  // namespace

void Image::CopyToBuffer(const CommandBuffer& cmd, const Buffer& buffer) const {
  cmd.copyImageToBuffer(*image_, ::vk::ImageLayout::eGeneral, buffer.handle(),
                        WholeImageCopy(extent_, format_));
}

void Image::CopyFromBuffer(const CommandBuffer& cmd, const Buffer& buffer) const {
  cmd.copyBufferToImage(buffer.handle(), *image_, ::vk::ImageLayout::eGeneral,
                        WholeImageCopy(extent_, format_));
}

void RecordCopyToHostBuffer(const CommandBuffer& cmd, ::vk::Image image, ::vk::ImageLayout layout, ::vk::Extent2D extent,
                            ::vk::Buffer buffer) {
  cmd.copyImageToBuffer(image, layout, buffer,
                        ::vk::BufferImageCopy{.imageSubresource = {.aspectMask = ::vk::ImageAspectFlagBits::eColor,
                                                                   .layerCount = 1},
                                              .imageExtent = {extent.width, extent.height, 1}});
  cmd.pipelineBarrier(::vk::PipelineStageFlagBits::eTransfer, ::vk::PipelineStageFlagBits::eHost, {},
                      ::vk::MemoryBarrier{.srcAccessMask = ::vk::AccessFlagBits::eTransferWrite,
                                          .dstAccessMask = ::vk::AccessFlagBits::eHostRead},
                      {}, {});
}

std::vector<std::byte> ReadImageBytes(const Context& context, const Image& image) {
  Buffer readback(context, {.size = image.byte_size(),
                            .usage = ::vk::BufferUsageFlagBits::eTransferDst,
                            .host_visible = true});
  context.Submit([&](const auto& cmd) {
    image.CopyToBuffer(cmd, readback);
    FullBarrier(cmd);
  });
  return {readback.mapped(), readback.mapped() + image.byte_size()};
}

std::vector<float> ReadImageFloats(const Context& context, const Image& image) {
  std::vector<std::byte> bytes = ReadImageBytes(context, image);
  std::vector<float> texels(bytes.size() / sizeof(float));
  std::memcpy(texels.data(), bytes.data(), texels.size() * sizeof(float));
  return texels;
}

BufferCreateInfo UniformBufferInfo(::vk::DeviceSize size) {
  return {.size = size, .usage = ::vk::BufferUsageFlagBits::eUniformBuffer, .host_visible = true};
}

BufferCreateInfo RecordedUniformBufferInfo(::vk::DeviceSize size) {
  return {.size = size, .usage = ::vk::BufferUsageFlagBits::eUniformBuffer | ::vk::BufferUsageFlagBits::eTransferDst};
}

ImageCreateInfo RenderTargetInfo(uint32_t width, uint32_t height, Format format) {
  ::vk::ImageUsageFlags attachment = format == kDepth32f ? ::vk::ImageUsageFlagBits::eDepthStencilAttachment
                                                         : ::vk::ImageUsageFlagBits::eColorAttachment;
  return {.extent = {width, height, 1},
          .format = format,
          .usage = attachment | ::vk::ImageUsageFlagBits::eSampled | ::vk::ImageUsageFlagBits::eTransferSrc};
}

namespace {
::vk::raii::Sampler CreateClampSampler(const Context& context, ::vk::Filter filter,
                                       std::optional<::vk::CompareOp> compare = std::nullopt) {
  return ::vk::raii::Sampler(
      context.device(), ::vk::SamplerCreateInfo{
                            .magFilter = filter,
                            .minFilter = filter,
                            .mipmapMode = ::vk::SamplerMipmapMode::eNearest,
                            .addressModeU = ::vk::SamplerAddressMode::eClampToEdge,
                            .addressModeV = ::vk::SamplerAddressMode::eClampToEdge,
                            .addressModeW = ::vk::SamplerAddressMode::eClampToEdge,
                            .compareEnable = compare.has_value(),
                            .compareOp = compare.value_or(::vk::CompareOp::eNever),
                            .maxLod = 0.0f});
}
}  // namespace

::vk::raii::Sampler CreateLinearClampSampler(const Context& context) {
  return CreateClampSampler(context, ::vk::Filter::eLinear);
}

::vk::raii::Sampler CreateNearestClampSampler(const Context& context) {
  return CreateClampSampler(context, ::vk::Filter::eNearest);
}

::vk::raii::Sampler CreateShadowMapSampler(const Context& context) {
  return CreateClampSampler(context, ::vk::Filter::eLinear, ::vk::CompareOp::eGreaterOrEqual);
}

void FullBarrier(const CommandBuffer& cmd) {
  // Everything before against everything after: passes are few and large, so finer barriers would
  // buy nothing on lavapipe and little on a GPU.
  ::vk::MemoryBarrier barrier{
      .srcAccessMask = ::vk::AccessFlagBits::eMemoryWrite,
      .dstAccessMask = ::vk::AccessFlagBits::eMemoryRead | ::vk::AccessFlagBits::eMemoryWrite};
  cmd.pipelineBarrier(::vk::PipelineStageFlagBits::eAllCommands,
                      ::vk::PipelineStageFlagBits::eAllCommands | ::vk::PipelineStageFlagBits::eHost,
                      {}, barrier, {}, {});
}

}  // namespace aerial::vk
