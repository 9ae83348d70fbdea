#include "aerial/vk/descriptors.h"

#include "aerial/error.h"
#include "aerial/vk/shader_registry.h"

namespace aerial::vk {

namespace {

// The descriptor type a slot's resource can fill.
::vk::DescriptorType SlotKind(const Slot& slot) {
  if (std::holds_alternative<UniformBufferSlot>(slot) || std::holds_alternative<UniformBlockSlot>(slot))
    return ::vk::DescriptorType::eUniformBuffer;
  if (std::holds_alternative<StorageBufferSlot>(slot)) return ::vk::DescriptorType::eStorageBuffer;
  if (std::holds_alternative<SampledImageSlot>(slot) || std::holds_alternative<SampledViewSlot>(slot))
    return ::vk::DescriptorType::eCombinedImageSampler;
  return ::vk::DescriptorType::eStorageImage;
}

}  // namespace

PushDescriptorLayout::PushDescriptorLayout(const Context& context, SlotLayout slot_layout, uint32_t push_bytes,
                                           ::vk::ShaderStageFlags stage_flags)
    : slots(std::move(slot_layout)), push_constant_bytes(push_bytes), stages(stage_flags) {
  std::vector<::vk::DescriptorSetLayoutBinding> bindings;
  for (uint32_t i = 0; i < slots.size(); ++i) {
    bindings.push_back({.binding = i, .descriptorType = slots[i].type, .descriptorCount = 1,
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
                                ::vk::PipelineBindPoint bind_point, const std::vector<Slot>& values,
                                const void* push_constants, const std::string& pipeline_name) const {
  if (values.size() != slots.size())
    throw Error(pipeline_name + " slots", std::to_string(values.size()), std::to_string(slots.size()));
  // The infos must stay at fixed addresses while the writes point at them.
  std::vector<::vk::DescriptorBufferInfo> buffer_infos(values.size());
  std::vector<::vk::DescriptorImageInfo> image_infos(values.size());
  std::vector<::vk::WriteDescriptorSet> writes;
  for (uint32_t i = 0; i < values.size(); ++i) {
    const Slot& slot = values[i];
    if (SlotKind(slot) != slots[i].type)
      throw Error(pipeline_name + " slot " + std::to_string(i) + " (" + slots[i].name + ")",
                  ::vk::to_string(SlotKind(slot)), ::vk::to_string(slots[i].type));
    ::vk::WriteDescriptorSet write{.dstBinding = i, .descriptorCount = 1, .descriptorType = slots[i].type};
    if (auto* u = std::get_if<UniformBufferSlot>(&slot)) {
      buffer_infos[i] = ::vk::DescriptorBufferInfo{.buffer = u->buffer->handle(), .range = VK_WHOLE_SIZE};
      write.pBufferInfo = &buffer_infos[i];
    } else if (auto* b = std::get_if<UniformBlockSlot>(&slot)) {
      buffer_infos[i] = ::vk::DescriptorBufferInfo{.buffer = b->buffer, .range = VK_WHOLE_SIZE};
      write.pBufferInfo = &buffer_infos[i];
    } else if (auto* v = std::get_if<SampledViewSlot>(&slot)) {
      image_infos[i] = ::vk::DescriptorImageInfo{.sampler = v->sampler, .imageView = v->view,
                                                 .imageLayout = ::vk::ImageLayout::eGeneral};
      write.pImageInfo = &image_infos[i];
    } else if (auto* s = std::get_if<StorageBufferSlot>(&slot)) {
      buffer_infos[i] = ::vk::DescriptorBufferInfo{.buffer = s->buffer->handle(), .range = VK_WHOLE_SIZE};
      write.pBufferInfo = &buffer_infos[i];
    } else if (auto* t = std::get_if<SampledImageSlot>(&slot)) {
      image_infos[i] = ::vk::DescriptorImageInfo{.sampler = t->sampler, .imageView = t->image->view(),
                                                 .imageLayout = ::vk::ImageLayout::eGeneral};
      write.pImageInfo = &image_infos[i];
    } else {
      image_infos[i] = ::vk::DescriptorImageInfo{
          .imageView = std::get<StorageImageSlot>(slot).image->view(),
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

::vk::raii::ShaderModule CreateShaderModule(const Context& context, const std::string& shader,
                                            const SlotLayout& slots) {
  std::span<const uint32_t> code = shaders::Find(shader);
  if (code.empty()) throw Error("shader", shader, "a shader compiled into this binary");
  CheckShaderBindings(shader, code, slots);
  return ::vk::raii::ShaderModule(
      context.device(),
      ::vk::ShaderModuleCreateInfo{.codeSize = code.size_bytes(), .pCode = code.data()});
}

}  // namespace aerial::vk
