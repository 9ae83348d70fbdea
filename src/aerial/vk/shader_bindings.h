#pragma once
// The descriptor bindings a shader declares, read from its SPIR-V (the SPIR-V specification,
// sections 2.3 and 3.32: OpName, OpDecorate Binding/DescriptorSet, OpVariable and the types it
// points to), and the check that a pipeline's named slot list agrees with them. A pipeline lists
// its slots by the names the shaders use; a binding moved or renamed in GLSL and not in C++ (or
// the other way round) then fails when the pipeline is made, naming the shader and the binding,
// instead of feeding a shader the wrong table.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.hpp>

namespace aerial::vk {

// One slot of a pipeline's descriptor set: the shaders' name for it (an image's uniform name,
// "transmittance_texture", or a block's type name, "AtmosphereBlock") and its descriptor type.
struct SlotSpec {
  std::string name;
  ::vk::DescriptorType type;
};
using SlotLayout = std::vector<SlotSpec>;  // binding i is SlotLayout[i]

struct ShaderBinding {
  uint32_t set = 0, binding = 0;
  std::string name;
  ::vk::DescriptorType type;
};

// Every resource variable of the module with a binding (uniform and storage blocks, combined image
// samplers, storage images), in the order the module declares them.
std::vector<ShaderBinding> ReflectShaderBindings(std::span<const uint32_t> spirv);

// Throws aerial::Error unless every binding the module declares is in set 0 and matches the slot
// of the same number by name and type. Slots the shader does not use are allowed (pipelines that
// share a layout).
void CheckShaderBindings(const std::string& shader, std::span<const uint32_t> spirv, const SlotLayout& slots);

}  // namespace aerial::vk
