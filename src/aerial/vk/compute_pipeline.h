#pragma once
// A compute pipeline built from an embedded SPIR-V module, with its descriptors pushed per dispatch
// (VK_KHR_push_descriptor): a pass declares its bindings once and binds resources by slot.
#include <string>
#include <variant>
#include <vector>

#include "aerial/vk/resources.h"

namespace aerial::vk {

struct UniformBufferSlot { const Buffer* buffer; };
struct StorageBufferSlot { const Buffer* buffer; };
struct SampledImageSlot { const Image* image; ::vk::Sampler sampler; };
struct StorageImageSlot { const Image* image; };
using Slot = std::variant<UniformBufferSlot, StorageBufferSlot, SampledImageSlot, StorageImageSlot>;

// Binding i of set 0 receives slots[i]: the order of a pass's slots is its binding numbers.
class ComputePipeline {
 public:
  // shader: the path under shaders/ ("precompute/transmittance.comp"). slot_types: one descriptor
  // type per binding, from 0. push_constant_bytes: 0 when the shader has none.
  ComputePipeline(const Context& context, const std::string& shader,
                  std::vector<::vk::DescriptorType> slot_types, uint32_t push_constant_bytes = 0);

  // Binds the pipeline, pushes the descriptors and constants, and dispatches enough workgroups of
  // `local_size` to cover `threads`.
  void Dispatch(const ::vk::raii::CommandBuffer& cmd, const std::vector<Slot>& slots,
                ::vk::Extent3D threads, ::vk::Extent3D local_size, const void* push_constants = nullptr) const;

  const std::string& name() const { return name_; }

 private:
  std::string name_;
  std::vector<::vk::DescriptorType> slot_types_;
  uint32_t push_constant_bytes_;
  ::vk::raii::DescriptorSetLayout set_layout_{nullptr};
  ::vk::raii::PipelineLayout layout_{nullptr};
  ::vk::raii::Pipeline pipeline_{nullptr};
};

// Descriptor types for slot lists, shorter to read in pass tables.
inline constexpr auto kUniform = ::vk::DescriptorType::eUniformBuffer;
inline constexpr auto kStorageBuffer = ::vk::DescriptorType::eStorageBuffer;
inline constexpr auto kSampled = ::vk::DescriptorType::eCombinedImageSampler;
inline constexpr auto kStorageImage = ::vk::DescriptorType::eStorageImage;

}  // namespace aerial::vk
