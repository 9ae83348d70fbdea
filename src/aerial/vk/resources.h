#pragma once
// Buffers, images and samplers with their memory. One allocation per resource: aerial creates a
// few dozen resources per table set, far below any allocation limit, so no sub-allocator is needed.
#include <cstddef>
#include <span>
#include <vector>

#include "aerial/vk/context.h"

namespace aerial::vk {

struct BufferCreateInfo {
  ::vk::DeviceSize size = 0;
  ::vk::BufferUsageFlags usage;
  bool host_visible = false;  // mapped for the whole lifetime (uniforms, readback, staging)
};

// A uniform block the CPU writes (once per frame, say) and shaders read.
BufferCreateInfo UniformBufferInfo(::vk::DeviceSize size);
// A uniform block that command buffers write (Buffer::RecordUpdate), so that frames in flight
// never see each other's values.
BufferCreateInfo RecordedUniformBufferInfo(::vk::DeviceSize size);

// Texel formats by what they hold: 32-bit floats, four, three or one per texel, and depth.
using Format = ::vk::Format;
inline constexpr Format kRgba32f = Format::eR32G32B32A32Sfloat;
inline constexpr Format kRgb32f = Format::eR32G32B32Sfloat;  // vertex attributes
inline constexpr Format kR32f = Format::eR32Sfloat;
inline constexpr Format kDepth32f = Format::eD32Sfloat;

class Buffer {
 public:
  Buffer(const Context& context, const BufferCreateInfo& info);
  ::vk::Buffer handle() const { return *buffer_; }
  ::vk::DeviceSize size() const { return size_; }
  std::byte* mapped() const { return mapped_; }
  void Write(std::span<const std::byte> bytes, ::vk::DeviceSize offset = 0);
  // Records a write of bytes (at most 65536, a multiple of 4) at the start of a buffer made with
  // TransferDst, between full barriers: after every earlier read, before every later one.
  void RecordUpdate(const CommandBuffer& cmd, std::span<const std::byte> bytes) const;

 private:
  ::vk::raii::Buffer buffer_;
  ::vk::raii::DeviceMemory memory_{nullptr};
  ::vk::DeviceSize size_;
  std::byte* mapped_ = nullptr;
};

struct ImageCreateInfo {
  ::vk::Extent3D extent;  // depth 1: a 2D image, unless volume is set
  bool volume = false;    // a 3D image even with depth 1 (a placeholder for a 3D table)
  Format format = kRgba32f;
  ::vk::ImageUsageFlags usage = ::vk::ImageUsageFlagBits::eStorage |
                                ::vk::ImageUsageFlagBits::eSampled |
                                ::vk::ImageUsageFlagBits::eTransferSrc |
                                ::vk::ImageUsageFlagBits::eTransferDst;
};

// A 2D image that raster passes draw into (a color target, or the depth target for kDepth32f)
// and that later passes sample or the CPU reads back (Granite's ImageCreateInfo::render_target).
ImageCreateInfo RenderTargetInfo(uint32_t width, uint32_t height, Format format);

// Images live in VK_IMAGE_LAYOUT_GENERAL after creation: every table is both written by compute
// passes and sampled by later ones.
class Image {
 public:
  Image(const Context& context, const ImageCreateInfo& info);
  ::vk::Image handle() const { return *image_; }
  ::vk::ImageView view() const { return *view_; }
  ::vk::Extent3D extent() const { return extent_; }
  ::vk::Format format() const { return format_; }
  bool is_3d() const { return volume_; }
  size_t texel_bytes() const;
  size_t byte_size() const;

  // Transitions to GENERAL; call once in the first command buffer that uses the image.
  void InitializeLayout(const CommandBuffer& cmd) const;
  void Clear(const CommandBuffer& cmd) const;
  void CopyToBuffer(const CommandBuffer& cmd, const Buffer& buffer) const;
  void CopyFromBuffer(const CommandBuffer& cmd, const Buffer& buffer) const;

 private:
  ::vk::raii::Image image_;
  ::vk::raii::DeviceMemory memory_{nullptr};
  ::vk::raii::ImageView view_{nullptr};
  ::vk::Extent3D extent_;
  ::vk::Format format_;
  bool volume_;
};

// Linear filtering with clamp-to-edge: the table mappings put every lookup on texel centers.
::vk::raii::Sampler CreateLinearClampSampler(const Context& context);
// Nearest texel, clamp-to-edge: for images read texel by texel (a depth buffer).
::vk::raii::Sampler CreateNearestClampSampler(const Context& context);
// Linear, clamp-to-edge, comparing, for sampler2DShadow: a lookup in a reversed-Z shadow map
// (depth 1 toward the light) with the receiver's depth as the reference is 1 (lit) where the
// receiver is at least as near the light as the caster, blended bilinearly over the four nearest
// texels (hardware PCF; shaders/include/shadow.glsl).
::vk::raii::Sampler CreateShadowMapSampler(const Context& context);

// Makes every earlier shader or transfer write visible to every later shader or transfer access.
void FullBarrier(const CommandBuffer& cmd);

// Records a copy of a 2D color image's texels (in `layout`, after every write to it was made
// available to transfers) into `buffer`, row by row, for the host to read once the submission's
// fence has passed.
void RecordCopyToHostBuffer(const CommandBuffer& cmd, ::vk::Image image, ::vk::ImageLayout layout, ::vk::Extent2D extent,
                            ::vk::Buffer buffer);

// The whole image's texels, copied to the host after every earlier GPU write (tightly packed, x
// fastest). ReadImageFloats: the same for a 32-bit float format.
std::vector<std::byte> ReadImageBytes(const Context& context, const Image& image);
std::vector<float> ReadImageFloats(const Context& context, const Image& image);

}  // namespace aerial::vk
