#pragma once
// Where the shaders' reads of the precomputed tables interpolate between texels
// (shaders/include/table_read.glsl), a specialization constant of every pipeline, chosen for a
// process by AERIAL_TABLE_FILTERING:
//  - sampler (the default): one filtered tap. Real GPUs interpolate with weights quantized to
//    subTexelPrecisionBits (8 on NVIDIA, AMD and Intel: 1/256 of a texel); lavapipe in float.
//  - shader: 4 or 8 texelFetch and the blend in float, the same on every device.
//  - emulated-hardware: the shader's blend with its weights rounded to 1/256, a GPU's sampler
//    emulated on lavapipe (to see whether the quantization moves the sky's accuracy).
// A specialization constant, not a uniform: lavapipe runs both sides of a uniform branch, and a
// uniform switch would more than double the froxel build.
#include <cstdint>
#include <string>

namespace aerial::vk {

enum class TableFiltering : int32_t { kSampler = 0, kShader = 1, kEmulatedHardware = 2 };

// The constant_id of TABLE_FILTERING in table_read.glsl; pipelines' own constants use 0, 1, 2...
constexpr uint32_t kTableFilteringConstantId = 16;

std::string ToString(TableFiltering filtering);  // "sampler" / "shader" / "emulated-hardware"
// Throws aerial::Error naming `field` and the value.
TableFiltering ParseTableFiltering(const std::string& text, const std::string& field);
// AERIAL_TABLE_FILTERING, or the sampler when it is unset or empty.
TableFiltering TableFilteringFromEnvironment();

}  // namespace aerial::vk
