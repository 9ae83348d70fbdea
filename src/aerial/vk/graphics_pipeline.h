#pragma once
// A raster pipeline: vertex and fragment modules from the embedded SPIR-V, at most one interleaved
// vertex buffer, push descriptors as for compute. It draws either with dynamic rendering (Vulkan
// 1.3) into plain Images, inside a Rendering scope, or inside a classic VkRenderPass (the
// swapchain's, which Dear ImGui's backend needs).
//
// A frame records one Rendering scope for all its raster passes, so that no barrier or image
// round trip separates them: Bind a pipeline, draw, Bind the next.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "aerial/vk/pipeline_cache.h"

namespace aerial::vk {

struct VertexAttribute {
  ::vk::Format format;
  uint32_t offset;
};

// Depth tests: the nearer fragment passes (reversed Z: the greater depth), only an equal one (a
// pass that draws where an earlier one left the cleared depth), or only a farther one (a pass at
// the cleared depth that draws where an earlier one drew).
inline constexpr ::vk::CompareOp kDepthNearer = ::vk::CompareOp::eGreater;
inline constexpr ::vk::CompareOp kDepthEqual = ::vk::CompareOp::eEqual;
inline constexpr ::vk::CompareOp kDepthFarther = ::vk::CompareOp::eLess;

struct GraphicsPipelineCreateInfo {
  std::string vertex_shader;    // "frame/opaque.vert"
  std::string fragment_shader;  // "frame/opaque.frag"; empty: none (a depth-only pass)
  SlotLayout slots;  // checked against both stages' bindings (shader_bindings.h)
  uint32_t push_constant_bytes = 0;
  uint32_t vertex_stride = 0;               // 0 with no attributes: no vertex buffer
  std::vector<VertexAttribute> attributes;  // location i = attributes[i]
  std::vector<::vk::Format> color_formats;  // dynamic rendering
  std::optional<::vk::Format> depth_format;
  ::vk::RenderPass render_pass = nullptr;   // set: draws in subpass 0 of it instead
  bool depth_write = true;
  ::vk::CompareOp depth_compare = kDepthNearer;
  bool alpha_blend = false;  // premultiplied: src + (1 - src_alpha) dst
  // The cull mode is dynamic state: every draw sets it (SetCullMode) before drawing.
  bool dynamic_cull_mode = false;
  ::vk::CullModeFlags cull = ::vk::CullModeFlagBits::eNone;
  // Specialization constants of both stages (specialization.h): constant_id i takes
  // specialization[i], e.g. aerial perspective per pixel or from froxels.
  std::vector<int32_t> specialization;
};

class GraphicsPipeline {
 public:
  // A pipeline the context built before for the same info is shared (pipeline_cache.h), but for
  // one that draws in a render pass.
  GraphicsPipeline(const Context& context, const GraphicsPipelineCreateInfo& info);

  // Binds the pipeline, pushes its descriptors and constants. Draws follow.
  void Bind(const CommandBuffer& cmd, const std::vector<Slot>& slots,
            const void* push_constants = nullptr) const;

 private:
  std::string name_;
  std::shared_ptr<const BuiltPipeline> built_;
};

struct RenderTargets {
  std::vector<const Image*> colors;
  std::vector<std::optional<std::array<float, 4>>> clear_colors;  // nullopt: load
  const Image* depth = nullptr;
  std::optional<float> clear_depth;  // nullopt: load
};

// Dynamic rendering into targets (GENERAL layout) for its lifetime, with the viewport and scissor
// covering the first target (or the depth target when there is no color).
class Rendering {
 public:
  Rendering(const CommandBuffer& cmd, const RenderTargets& targets);
  ~Rendering();
  Rendering(const Rendering&) = delete;
  Rendering& operator=(const Rendering&) = delete;

 private:
  const CommandBuffer& cmd_;
};

// The viewport and scissor of a rectangle (by default the whole extent from the origin).
void SetViewport(const CommandBuffer& cmd, ::vk::Extent2D extent, ::vk::Offset2D offset = {});
// Narrows the scissor to a rectangle within the viewport.
void SetScissor(const CommandBuffer& cmd, const ::vk::Rect2D& rect);
// Inside a Rendering scope: sets the depth target to `depth` within the rectangle alone.
void ClearDepth(const CommandBuffer& cmd, const ::vk::Rect2D& rect, float depth);
void SetCullMode(const CommandBuffer& cmd, ::vk::CullModeFlags mode);
void BindMesh(const CommandBuffer& cmd, const Buffer& vertices, const Buffer& indices);
// One instance, numbered first_instance (gl_InstanceIndex): a draw's own number for its shaders.
void DrawIndexed(const CommandBuffer& cmd, uint32_t index_count, uint32_t first_index = 0,
                 int32_t vertex_offset = 0, uint32_t first_instance = 0);
// Three vertices and no buffers: a triangle the vertex shader makes from gl_VertexIndex (over the
// whole screen, or around the sun's disc).
void DrawGeneratedTriangle(const CommandBuffer& cmd);

}  // namespace aerial::vk
