#pragma once
// What compute and graphics pipelines share: a pipeline layout of one push-descriptor set plus push
// constants, pushing the descriptors of a list of slots, and shader modules from the embedded
// SPIR-V.
#include <string>
#include <variant>
#include <vector>

#include "aerial/vk/resources.h"
#include "aerial/vk/shader_bindings.h"

namespace aerial::vk {

struct UniformBufferSlot { const Buffer* buffer; };
struct StorageBufferSlot { const Buffer* buffer; };
struct SampledImageSlot { const Image* image; ::vk::Sampler sampler; };
struct StorageImageSlot { const Image* image; };
// A buffer or an image that the public API handed out (aerial/tables.h: UniformBlock,
// SampledImage) rather than one of this layer's objects: the viewer binds aerial's images so.
struct UniformBlockSlot { ::vk::Buffer buffer; };
struct SampledViewSlot { ::vk::ImageView view; ::vk::Sampler sampler; };
using Slot = std::variant<UniformBufferSlot, StorageBufferSlot, SampledImageSlot, StorageImageSlot, UniformBlockSlot,
                          SampledViewSlot>;

// Descriptor types for slot lists (SlotLayout, shader_bindings.h), shorter to read in pass tables.
inline constexpr auto kUniform = ::vk::DescriptorType::eUniformBuffer;
inline constexpr auto kStorageBuffer = ::vk::DescriptorType::eStorageBuffer;
inline constexpr auto kSampled = ::vk::DescriptorType::eCombinedImageSampler;
inline constexpr auto kStorageImage = ::vk::DescriptorType::eStorageImage;

// Binding i of set 0 is slots[i]; push constants, if any, start at offset 0.
struct PushDescriptorLayout {
  PushDescriptorLayout(const Context& context, SlotLayout slots, uint32_t push_constant_bytes,
                       ::vk::ShaderStageFlags stages);

  // Pushes slots[i] to binding i and the push constants (when the layout has them). Throws
  // aerial::Error when a slot's kind is not its binding's type.
  void Push(const CommandBuffer& cmd, ::vk::PipelineBindPoint bind_point,
            const std::vector<Slot>& slots, const void* push_constants,
            const std::string& pipeline_name) const;

  SlotLayout slots;
  uint32_t push_constant_bytes;
  ::vk::ShaderStageFlags stages;
  ::vk::raii::DescriptorSetLayout set_layout{nullptr};
  ::vk::raii::PipelineLayout layout{nullptr};
};

// Throws aerial::Error when the name is not one of shaders/, or when its bindings do not match
// slots by name and type (CheckShaderBindings).
::vk::raii::ShaderModule CreateShaderModule(const Context& context, const std::string& shader, const SlotLayout& slots);

}  // namespace aerial::vk
