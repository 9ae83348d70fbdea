#pragma once
// A compute pipeline built from an embedded SPIR-V module, with its descriptors pushed per dispatch
// (VK_KHR_push_descriptor): a pass declares its bindings once and binds resources by slot.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "aerial/vk/pipeline_cache.h"

namespace aerial::vk {

// Binding i of set 0 receives slots[i]: the order of a pass's slots is its binding numbers.
class ComputePipeline {
 public:
  // shader: the path under shaders/ ("precompute/transmittance.comp"). slots: one named slot per
  // binding, from 0, checked against the shader's (shader_bindings.h). push_constant_bytes: 0
  // when the shader has none. specialization: constant_id i takes specialization[i]
  // (specialization.h). A pipeline the context built before for the same arguments is shared
  // (pipeline_cache.h).
  ComputePipeline(const Context& context, const std::string& shader, SlotLayout slots,
                  uint32_t push_constant_bytes = 0, std::vector<int32_t> specialization = {});

  // Binds the pipeline, pushes the descriptors and constants, and dispatches enough workgroups of
  // `local_size` to cover `threads`.
  void Dispatch(const CommandBuffer& cmd, const std::vector<Slot>& slots,
                ::vk::Extent3D threads, ::vk::Extent3D local_size,
                const void* push_constants = nullptr) const;

  // The same with the workgroup counts read from `args` at `offset` when the commands run
  // (a VkDispatchIndirectCommand, written by an earlier pass).
  void DispatchIndirect(const CommandBuffer& cmd, const std::vector<Slot>& slots, const Buffer& args,
                        ::vk::DeviceSize offset = 0, const void* push_constants = nullptr) const;

  const std::string& name() const { return name_; }

 private:
  std::string name_;
  std::shared_ptr<const BuiltPipeline> built_;
};

}  // namespace aerial::vk
