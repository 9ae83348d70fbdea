#include "aerial/vk/compute_pipeline.h"

#include "aerial/vk/specialization.h"

namespace aerial::vk {

ComputePipeline::ComputePipeline(const Context& context, const std::string& shader,
                                 SlotLayout slots, uint32_t push_constant_bytes,
                                 std::vector<int32_t> specialization)
    : name_(shader) {
  PipelineKey key;
  key.Add("compute").Add(shader).Add(slots).Add(push_constant_bytes).Add(specialization);
  built_ = context.pipelines().Get(key, [&] {
    PushDescriptorLayout layout(context, std::move(slots), push_constant_bytes, ::vk::ShaderStageFlagBits::eCompute);
    ::vk::raii::ShaderModule module = CreateShaderModule(context, shader, layout.slots);
    Specialization constants(std::move(specialization), context.table_filtering());
    ::vk::raii::Pipeline pipeline(
        context.device(), nullptr,
        ::vk::ComputePipelineCreateInfo{
            .stage = {.stage = ::vk::ShaderStageFlagBits::eCompute, .module = *module, .pName = "main",
                      .pSpecializationInfo = constants.info()},
            .layout = *layout.layout});
    return std::make_shared<const BuiltPipeline>(BuiltPipeline{std::move(layout), std::move(pipeline)});
  });
}

void ComputePipeline::Dispatch(const CommandBuffer& cmd, const std::vector<Slot>& slots,
                               ::vk::Extent3D threads, ::vk::Extent3D local_size,
                               const void* push_constants) const {
  cmd.bindPipeline(::vk::PipelineBindPoint::eCompute, *built_->pipeline);
  built_->layout.Push(cmd, ::vk::PipelineBindPoint::eCompute, slots, push_constants, name_);
  auto groups = [](uint32_t n, uint32_t size) { return (n + size - 1) / size; };
  cmd.dispatch(groups(threads.width, local_size.width), groups(threads.height, local_size.height),
               groups(threads.depth, local_size.depth));
}

void ComputePipeline::DispatchIndirect(const CommandBuffer& cmd, const std::vector<Slot>& slots, const Buffer& args,
                                       ::vk::DeviceSize offset, const void* push_constants) const {
  cmd.bindPipeline(::vk::PipelineBindPoint::eCompute, *built_->pipeline);
  built_->layout.Push(cmd, ::vk::PipelineBindPoint::eCompute, slots, push_constants, name_);
  cmd.dispatchIndirect(args.handle(), offset);
}

}  // namespace aerial::vk
