#include "aerial/vk/compute_pipeline.h"

#include "aerial/core/error.h"
#include "aerial/vk/shader_registry.h"

namespace aerial::vk {

ComputePipeline::ComputePipeline(const Context& context, const std::string& shader,
                                 std::vector<::vk::DescriptorType> slot_types,
                                 uint32_t push_constant_bytes)
    : name_(shader), slot_types_(std::move(slot_types)), push_constant_bytes_(push_constant_bytes) {
  std::span<const uint32_t> code = shaders::Find(shader);
  if (code.empty()) throw Error("shader", shader, "a shader compiled into this binary");

  std::vector<::vk::DescriptorSetLayoutBinding> bindings;
  for (uint32_t i = 0; i < slot_types_.size(); ++i) {
    bindings.push_back({.binding = i,
                        .descriptorType = slot_types_[i],
                        .descriptorCount = 1,
                        .stageFlags = ::vk::ShaderStageFlagBits::eCompute});
  }
  set_layout_ = ::vk::raii::DescriptorSetLayout(
      context.device(),
      ::vk::DescriptorSetLayoutCreateInfo{
          .flags = ::vk::DescriptorSetLayoutCreateFlagBits::ePushDescriptorKHR,
          .bindingCount = uint32_t(bindings.size()),
          .pBindings = bindings.data()});
  ::vk::PushConstantRange range{.stageFlags = ::vk::ShaderStageFlagBits::eCompute,
                                .size = push_constant_bytes_};
  ::vk::DescriptorSetLayout raw_set_layout = *set_layout_;
  layout_ = ::vk::raii::PipelineLayout(
      context.device(),
      ::vk::PipelineLayoutCreateInfo{.setLayoutCount = 1,
                                     .pSetLayouts = &raw_set_layout,
                                     .pushConstantRangeCount = push_constant_bytes_ ? 1u : 0u,
                                     .pPushConstantRanges = &range});
  ::vk::raii::ShaderModule module(
      context.device(),
      ::vk::ShaderModuleCreateInfo{.codeSize = code.size_bytes(), .pCode = code.data()});
  pipeline_ = ::vk::raii::Pipeline(
      context.device(), nullptr,
      ::vk::ComputePipelineCreateInfo{
          .stage = {.stage = ::vk::ShaderStageFlagBits::eCompute, .module = *module, .pName = "main"},
          .layout = *layout_});
}

void ComputePipeline::Dispatch(const ::vk::raii::CommandBuffer& cmd, const std::vector<Slot>& slots,
                               ::vk::Extent3D threads, ::vk::Extent3D local_size,
                               const void* push_constants) const {
  if (slots.size() != slot_types_.size())
    throw Error(name_ + " slots", std::to_string(slots.size()), std::to_string(slot_types_.size()));
  // The infos must stay at fixed addresses while the writes point at them.
  std::vector<::vk::DescriptorBufferInfo> buffer_infos(slots.size());
  std::vector<::vk::DescriptorImageInfo> image_infos(slots.size());
  std::vector<::vk::WriteDescriptorSet> writes;
  for (uint32_t i = 0; i < slots.size(); ++i) {
    ::vk::WriteDescriptorSet write{.dstBinding = i, .descriptorCount = 1, .descriptorType = slot_types_[i]};
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
      image_infos[i] = ::vk::DescriptorImageInfo{.imageView = std::get<StorageImageSlot>(slots[i]).image->view(),
                        .imageLayout = ::vk::ImageLayout::eGeneral};
      write.pImageInfo = &image_infos[i];
    }
    writes.push_back(write);
  }
  cmd.bindPipeline(::vk::PipelineBindPoint::eCompute, *pipeline_);
  cmd.pushDescriptorSetKHR(::vk::PipelineBindPoint::eCompute, *layout_, 0, writes);
  if (push_constant_bytes_ && push_constants) {
    cmd.pushConstants<std::byte>(*layout_, ::vk::ShaderStageFlagBits::eCompute, 0,
                                 std::span(static_cast<const std::byte*>(push_constants),
                                           push_constant_bytes_));
  }
  auto groups = [](uint32_t n, uint32_t size) { return (n + size - 1) / size; };
  cmd.dispatch(groups(threads.width, local_size.width), groups(threads.height, local_size.height),
               groups(threads.depth, local_size.depth));
}

}  // namespace aerial::vk
