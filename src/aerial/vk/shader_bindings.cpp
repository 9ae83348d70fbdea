#include "aerial/vk/shader_bindings.h"

#include <map>
#include <set>

#include "aerial/error.h"

namespace aerial::vk {
namespace {

// Opcodes, decorations and storage classes of the SPIR-V specification (section 3).
enum Op : uint32_t {
  kOpName = 5, kOpTypeImage = 25, kOpTypeSampledImage = 27, kOpTypeArray = 28,
  kOpTypeStruct = 30, kOpTypePointer = 32, kOpVariable = 59, kOpDecorate = 71,
};
enum Decoration : uint32_t { kBlock = 2, kBufferBlock = 3, kBinding = 33, kDescriptorSet = 34 };
enum StorageClass : uint32_t { kUniformConstant = 0, kUniform = 2, kStorageBuffer = 12 };
constexpr size_t kHeaderWords = 5;

std::string LiteralString(std::span<const uint32_t> words) {
  std::string text;
  for (uint32_t word : words)
    for (int byte = 0; byte < 4; ++byte) {
      char c = char((word >> (8 * byte)) & 0xff);
      if (c == '\0') return text;
      text.push_back(c);
    }
  return text;
}

}  // namespace

std::vector<ShaderBinding> ReflectShaderBindings(std::span<const uint32_t> spirv) {
  std::map<uint32_t, std::string> names;
  std::map<uint32_t, uint32_t> bindings, sets;
  std::map<uint32_t, uint32_t> block_kind;      // struct id -> kBlock or kBufferBlock
  std::map<uint32_t, uint32_t> image_sampled;   // image type id -> its Sampled operand
  std::map<uint32_t, uint32_t> pointee;         // pointer type id -> pointee type id
  std::map<uint32_t, uint32_t> element;         // array type id -> element type id
  std::set<uint32_t> sampled_image_types, struct_types;
  struct Variable { uint32_t id, pointer_type, storage; };
  std::vector<Variable> variables;
  for (size_t i = kHeaderWords; i < spirv.size();) {
    uint32_t count = spirv[i] >> 16, op = spirv[i] & 0xffff;
    if (count == 0 || i + count > spirv.size()) throw Error("SPIR-V module", "a truncated instruction", "whole instructions");
    std::span<const uint32_t> w = spirv.subspan(i, count);
    switch (op) {
      case kOpName: names[w[1]] = LiteralString(w.subspan(2)); break;
      case kOpDecorate:
        if (w[2] == kBinding) bindings[w[1]] = w[3];
        if (w[2] == kDescriptorSet) sets[w[1]] = w[3];
        if (w[2] == kBlock || w[2] == kBufferBlock) block_kind[w[1]] = w[2];
        break;
      case kOpTypeImage: image_sampled[w[1]] = w[7]; break;
      case kOpTypeSampledImage: sampled_image_types.insert(w[1]); break;
      case kOpTypeArray: element[w[1]] = w[2]; break;
      case kOpTypeStruct: struct_types.insert(w[1]); break;
      case kOpTypePointer: pointee[w[1]] = w[3]; break;
      case kOpVariable: variables.push_back({w[2], w[1], w[3]}); break;
      default: break;
    }
    i += count;
  }
  std::vector<ShaderBinding> result;
  for (const Variable& v : variables) {
    if (!bindings.contains(v.id)) continue;
    uint32_t type = pointee[v.pointer_type];
    if (element.contains(type)) type = element[type];
    ShaderBinding binding{.set = sets[v.id], .binding = bindings[v.id], .name = names[v.id]};
    if (sampled_image_types.contains(type)) {
      binding.type = ::vk::DescriptorType::eCombinedImageSampler;
    } else if (image_sampled.contains(type)) {
      binding.type = image_sampled[type] == 2 ? ::vk::DescriptorType::eStorageImage
                                              : ::vk::DescriptorType::eSampledImage;
    } else if (struct_types.contains(type)) {
      bool storage = v.storage == kStorageBuffer || block_kind[type] == kBufferBlock;
      binding.type = storage ? ::vk::DescriptorType::eStorageBuffer : ::vk::DescriptorType::eUniformBuffer;
      binding.name = names[type];  // blocks go by their type's name
    } else {
      continue;  // not a resource aerial binds
    }
    result.push_back(binding);
  }
  return result;
}

void CheckShaderBindings(const std::string& shader, std::span<const uint32_t> spirv, const SlotLayout& slots) {
  for (const ShaderBinding& b : ReflectShaderBindings(spirv)) {
    std::string where = shader + " binding " + std::to_string(b.binding) + " (" + b.name + ")";
    if (b.set != 0) throw Error(where + " set", std::to_string(b.set), "0 (aerial pushes one descriptor set)");
    if (b.binding >= slots.size())
      throw Error(where, "not in the pipeline's slots", std::to_string(slots.size()) + " slots");
    const SlotSpec& slot = slots[b.binding];
    if (slot.name != b.name) throw Error(where + " name", slot.name + " in the pipeline", b.name);
    if (slot.type != b.type)
      throw Error(where + " type", ::vk::to_string(slot.type) + " in the pipeline", ::vk::to_string(b.type));
  }
}

}  // namespace aerial::vk
