#include "aerial/vk/descriptors.h"

#include "aerial/core/error.h"
#include "aerial/vk/shader_registry.h"

namespace aerial::vk {

PushDescriptorLayout::PushDescriptorLayout(const Context& context,
                                           std::vector<::vk::DescriptorType> types,
                                           uint32_t push_bytes, ::vk::ShaderStageFlags stage_flags)
    : slot_types(std::move(types)), push_constant_bytes(push_bytes), stages(stage_flags) {
  std::vector<::vk::DescriptorSetLayoutBinding> bindings;
  for (uint32_t i = 0; i < slot_types.size(); ++i) {
    bindings.push_back({.binding = i, .descriptorType = slot_types[i], .descriptorCount = 1,
                        .stageFlags = stages});
  }
  set_layout = ::vk::raii::DescriptorSetLayout(
      context.device(),
      ::vk::DescriptorSetLayoutCreateInfo{
          .flags = ::vk::DescriptorSetLayoutCreateFlagBits::ePushDescriptorKHR,
          .bindingCount = uint32_t(bindings.size()),
          .pBindings = bindings.data()});
  ::vk::PushConstantRange range{.stageFlags = stages, .size = push_constant_bytes};
  ::vk::DescriptorSetLayout raw_set_layout = *set_layout;
  layout = ::vk::raii::PipelineLayout(
      context.device(),
      ::vk::PipelineLayoutCreateInfo{.setLayoutCount = 1,
                                     .pSetLayouts = &raw_set_layout,
                                     .pushConstantRangeCount = push_constant_bytes ? 1u : 0u,
                                     .pPushConstantRanges = &range});
}

void PushDescriptorLayout::Push(const CommandBuffer& cmd,
                                ::vk::PipelineBindPoint bind_point, const std::vector<Slot>& slots,
                                const void* push_constants, const std::string& pipeline_name) const {
  if (slots.size() != slot_types.size())
    throw Error(pipeline_name + " slots", std::to_string(slots.size()),
                std::to_string(slot_types.size()));
  // The infos must stay at fixed addresses while the writes point at them.
  std::vector<::vk::DescriptorBufferInfo> buffer_infos(slots.size());
  std::vector<::vk::DescriptorImageInfo> image_infos(slots.size());
  std::vector<::vk::WriteDescriptorSet> writes;
  for (uint32_t i = 0; i < slots.size(); ++i) {
    ::vk::WriteDescriptorSet write{.dstBinding = i, .descriptorCount = 1, .descriptorType = slot_types[i]};
    if (auto* u = std::get_if<UniformBufferSlot>(&slots[i])) {
      buffer_infos[i] = ::vk::DescriptorBufferInfo{.buffer = u->buffer->handle(), .range = VK_WHOLE_SIZE};
      write.pBufferInfo = &buffer_infos[i];
    } else if (auto* s = std::get_if<StorageBufferSlot>(&slots[i])) {
      buffer_infos[i] = ::vk::DescriptorBufferInfo{.buffer = s->buffer->handle(), .range = VK_WHOLE_SIZE};
      write.pBufferInfo = &buffer_infos[i];
    } else if (auto* t = std::get_if<SampledImageSlot>(&slots[i])) {
      image_infos[i] = ::vk::DescriptorImageInfo{.sampler = t->sampler, .imageView = t->image->view(),
                                                 .imageLayout = ::vk::ImageLayout::eGeneral};
      write.pImageInfo = &image_infos[i];
    } else {
      image_infos[i] = ::vk::DescriptorImageInfo{
          .imageView = std::get<StorageImageSlot>(slots[i]).image->view(),
          .imageLayout = ::vk::ImageLayout::eGeneral};
      write.pImageInfo = &image_infos[i];
    }
    writes.push_back(write);
  }
  if (!writes.empty()) cmd.pushDescriptorSetKHR(bind_point, *layout, 0, writes);
  if (push_constant_bytes && push_constants) {
    cmd.pushConstants<std::byte>(*layout, stages, 0,
                                 std::span(static_cast<const std::byte*>(push_constants),
                                           push_constant_bytes));
  }
}

::vk::raii::ShaderModule CreateShaderModule(const Context& context, const std::string& shader) {
  std::span<const uint32_t> code = shaders::Find(shader);
  if (code.empty()) throw Error("shader", shader, "a shader compiled into this binary");
  return ::vk::raii::ShaderModule(
      context.device(),
      ::vk::ShaderModuleCreateInfo{.codeSize = code.size_bytes(), .pCode = code.data()});
}

}  // namespace aerial::vk
