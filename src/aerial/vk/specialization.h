#pragma once
// Specialization constants of a pipeline's shader stages: constant_id i takes values[i], and
// kTableFilteringConstantId the context's table filtering (table_filtering.h). A CPU rasterizer
// executes both sides of every branch its SIMD lanes reach, so choices that are fixed for a
// pipeline must be constants, not uniforms or push constants.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.hpp>

#include "aerial/vk/table_filtering.h"

namespace aerial::vk {

class Specialization {
 public:
  Specialization(std::vector<int32_t> values, TableFiltering filtering);
  Specialization(const Specialization&) = delete;  // info() points into the object
  Specialization& operator=(const Specialization&) = delete;

  // For PipelineShaderStageCreateInfo::pSpecializationInfo. An entry whose constant_id the shader
  // does not declare has no effect (Vulkan 1.3, VkSpecializationInfo).
  const ::vk::SpecializationInfo* info() const { return &info_; }

 private:
  std::vector<int32_t> values_;
  std::vector<::vk::SpecializationMapEntry> entries_;
  ::vk::SpecializationInfo info_;
};

}  // namespace aerial::vk
