#pragma once
// Specialization constants of a pipeline's shader stages: constant_id i takes values[i]. A CPU
// rasterizer executes both sides of every branch its SIMD lanes reach, so choices that are fixed
// for a pipeline must be constants, not uniforms or push constants.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.hpp>

namespace aerial::vk {

class Specialization {
 public:
  explicit Specialization(std::vector<int32_t> values);
  Specialization(const Specialization&) = delete;  // info() points into the object
  Specialization& operator=(const Specialization&) = delete;

  // For PipelineShaderStageCreateInfo::pSpecializationInfo; null with no constants.
  const ::vk::SpecializationInfo* info() const { return values_.empty() ? nullptr : &info_; }

 private:
  std::vector<int32_t> values_;
  std::vector<::vk::SpecializationMapEntry> entries_;
  ::vk::SpecializationInfo info_;
};

}  // namespace aerial::vk
