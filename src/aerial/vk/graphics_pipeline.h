#pragma once
// A raster pipeline for dynamic rendering (Vulkan 1.3): vertex and fragment modules from the
// embedded SPIR-V, one interleaved vertex buffer, push descriptors as for compute. Render targets
// are plain Images; Draw begins and ends the rendering around the recorded draw.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <array>

#include "aerial/vk/descriptors.h"

namespace aerial::vk {

struct VertexAttribute {
  ::vk::Format format;
  uint32_t offset;
};

struct GraphicsPipelineCreateInfo {
  std::string vertex_shader;    // "frame/opaque.vert"
  std::string fragment_shader;  // "frame/opaque.frag"
  std::vector<::vk::DescriptorType> slot_types;
  uint32_t push_constant_bytes = 0;
  uint32_t vertex_stride = 0;
  std::vector<VertexAttribute> attributes;  // location i = attributes[i]
  std::vector<::vk::Format> color_formats;
  std::optional<::vk::Format> depth_format;
  bool depth_write = true;
  ::vk::CompareOp depth_compare = ::vk::CompareOp::eGreater;  // reversed-Z
  bool alpha_blend = false;  // premultiplied: src + (1 - src_alpha) dst
  ::vk::CullModeFlags cull = ::vk::CullModeFlagBits::eNone;
  // Specialization constants of both stages: constant_id i takes specialization[i]. A CPU
  // rasterizer executes both sides of every branch its SIMD lanes reach, so choices that are fixed
  // for a pipeline (aerial perspective per pixel or from froxels) must be constants, not uniforms.
  std::vector<int32_t> specialization;
};

struct RenderTargets {
  std::vector<const Image*> colors;
  std::vector<std::optional<std::array<float, 4>>> clear_colors;  // nullopt: load
  const Image* depth = nullptr;
  std::optional<float> clear_depth;  // nullopt: load
};

class GraphicsPipeline {
 public:
  GraphicsPipeline(const Context& context, const GraphicsPipelineCreateInfo& info);

  // Begins rendering into targets (all in GENERAL layout), binds everything, draws `index_count`
  // indices, ends rendering.
  void Draw(const ::vk::raii::CommandBuffer& cmd, const RenderTargets& targets,
            const std::vector<Slot>& slots, const Buffer& vertices, const Buffer& indices,
            uint32_t index_count, const void* push_constants = nullptr) const;

 private:
  std::string name_;
  PushDescriptorLayout layout_;
  ::vk::raii::Pipeline pipeline_{nullptr};
};

}  // namespace aerial::vk
