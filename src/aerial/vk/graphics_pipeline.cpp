#include "aerial/vk/graphics_pipeline.h"

#include "aerial/error.h"
#include "aerial/vk/specialization.h"

namespace aerial::vk {

namespace {

std::shared_ptr<const BuiltPipeline> Build(const Context& context, const GraphicsPipelineCreateInfo& info) {
  PushDescriptorLayout layout(context, info.slots, info.push_constant_bytes,
                              ::vk::ShaderStageFlagBits::eVertex | ::vk::ShaderStageFlagBits::eFragment);
  ::vk::raii::ShaderModule vertex = CreateShaderModule(context, info.vertex_shader, info.slots);
  bool has_fragment = !info.fragment_shader.empty();
  ::vk::raii::ShaderModule fragment =
      has_fragment ? CreateShaderModule(context, info.fragment_shader, info.slots) : ::vk::raii::ShaderModule(nullptr);
  Specialization specialization(info.specialization, context.table_filtering());
  const ::vk::SpecializationInfo* constants = specialization.info();
  std::array<::vk::PipelineShaderStageCreateInfo, 2> stages = {
      ::vk::PipelineShaderStageCreateInfo{.stage = ::vk::ShaderStageFlagBits::eVertex,
                                          .module = *vertex, .pName = "main",
                                          .pSpecializationInfo = constants},
      ::vk::PipelineShaderStageCreateInfo{.stage = ::vk::ShaderStageFlagBits::eFragment,
                                          .module = has_fragment ? *fragment : ::vk::ShaderModule{},
                                          .pName = "main", .pSpecializationInfo = constants}};
  ::vk::VertexInputBindingDescription binding{.binding = 0, .stride = info.vertex_stride,
                                              .inputRate = ::vk::VertexInputRate::eVertex};
  std::vector<::vk::VertexInputAttributeDescription> attributes;
  for (uint32_t i = 0; i < info.attributes.size(); ++i)
    attributes.push_back({.location = i, .binding = 0, .format = info.attributes[i].format,
                          .offset = info.attributes[i].offset});
  bool has_vertices = !attributes.empty();
  ::vk::PipelineVertexInputStateCreateInfo vertex_input{
      .vertexBindingDescriptionCount = has_vertices ? 1u : 0u,
      .pVertexBindingDescriptions = has_vertices ? &binding : nullptr,
      .vertexAttributeDescriptionCount = uint32_t(attributes.size()),
      .pVertexAttributeDescriptions = attributes.data()};
  ::vk::PipelineInputAssemblyStateCreateInfo assembly{.topology = ::vk::PrimitiveTopology::eTriangleList};
  ::vk::PipelineViewportStateCreateInfo viewport{.viewportCount = 1, .scissorCount = 1};
  ::vk::PipelineRasterizationStateCreateInfo raster{.polygonMode = ::vk::PolygonMode::eFill,
                                                    .cullMode = info.cull,
                                                    .frontFace = ::vk::FrontFace::eCounterClockwise,
                                                    .lineWidth = 1.0f};
  ::vk::PipelineMultisampleStateCreateInfo multisample{.rasterizationSamples = ::vk::SampleCountFlagBits::e1};
  ::vk::PipelineDepthStencilStateCreateInfo depth{.depthTestEnable = info.depth_format.has_value(),
                                                  .depthWriteEnable = info.depth_write,
                                                  .depthCompareOp = info.depth_compare};
  // Premultiplied alpha: the fragment shader outputs color * alpha and alpha.
  ::vk::PipelineColorBlendAttachmentState blend{
      .blendEnable = info.alpha_blend,
      .srcColorBlendFactor = ::vk::BlendFactor::eOne,
      .dstColorBlendFactor = ::vk::BlendFactor::eOneMinusSrcAlpha,
      .colorBlendOp = ::vk::BlendOp::eAdd,
      .srcAlphaBlendFactor = ::vk::BlendFactor::eOne,
      .dstAlphaBlendFactor = ::vk::BlendFactor::eOneMinusSrcAlpha,
      .alphaBlendOp = ::vk::BlendOp::eAdd,
      .colorWriteMask = ::vk::ColorComponentFlagBits::eR | ::vk::ColorComponentFlagBits::eG |
                        ::vk::ColorComponentFlagBits::eB | ::vk::ColorComponentFlagBits::eA};
  size_t color_count = info.render_pass ? 1 : info.color_formats.size();
  std::vector<::vk::PipelineColorBlendAttachmentState> blends(color_count, blend);
  ::vk::PipelineColorBlendStateCreateInfo color_blend{.attachmentCount = uint32_t(blends.size()),
                                                      .pAttachments = blends.data()};
  std::vector<::vk::DynamicState> dynamic_states = {::vk::DynamicState::eViewport,
                                                    ::vk::DynamicState::eScissor};
  if (info.dynamic_cull_mode) dynamic_states.push_back(::vk::DynamicState::eCullMode);
  ::vk::PipelineDynamicStateCreateInfo dynamic{.dynamicStateCount = uint32_t(dynamic_states.size()),
                                               .pDynamicStates = dynamic_states.data()};
  ::vk::PipelineRenderingCreateInfo rendering{
      .colorAttachmentCount = uint32_t(info.color_formats.size()),
      .pColorAttachmentFormats = info.color_formats.data(),
      .depthAttachmentFormat = info.depth_format.value_or(::vk::Format::eUndefined)};
  ::vk::raii::Pipeline pipeline(
      context.device(), nullptr,
      ::vk::GraphicsPipelineCreateInfo{.pNext = info.render_pass ? nullptr : &rendering,
                                       .stageCount = has_fragment ? 2u : 1u,
                                       .pStages = stages.data(),
                                       .pVertexInputState = &vertex_input,
                                       .pInputAssemblyState = &assembly,
                                       .pViewportState = &viewport,
                                       .pRasterizationState = &raster,
                                       .pMultisampleState = &multisample,
                                       .pDepthStencilState = &depth,
                                       .pColorBlendState = &color_blend,
                                       .pDynamicState = &dynamic,
                                       .layout = *layout.layout,
                                       .renderPass = info.render_pass});
  return std::make_shared<const BuiltPipeline>(BuiltPipeline{std::move(layout), std::move(pipeline)});
}

}  // namespace

GraphicsPipeline::GraphicsPipeline(const Context& context, const GraphicsPipelineCreateInfo& info)
    : name_(info.vertex_shader + "+" + info.fragment_shader) {
  // A render pass's handle may be reused by a later, different one: those pipelines are not shared.
  if (info.render_pass) {
    built_ = Build(context, info);
    return;
  }
  PipelineKey key;
  key.Add("graphics").Add(info.vertex_shader).Add(info.fragment_shader).Add(info.slots).Add(info.push_constant_bytes);
  key.Add(info.vertex_stride).Add(info.attributes.size());
  for (const VertexAttribute& attribute : info.attributes) key.Add(uint64_t(attribute.format)).Add(attribute.offset);
  key.Add(info.color_formats.size());
  for (::vk::Format format : info.color_formats) key.Add(uint64_t(format));
  key.Add(info.depth_format ? uint64_t(*info.depth_format) + 1 : 0).Add(info.depth_write).Add(uint64_t(info.depth_compare));
  key.Add(info.alpha_blend).Add(info.dynamic_cull_mode).Add(uint64_t(uint32_t(info.cull))).Add(info.specialization);
  built_ = context.pipelines().Get(key, [&] { return Build(context, info); });
}

void GraphicsPipeline::Bind(const CommandBuffer& cmd, const std::vector<Slot>& slots,
                            const void* push_constants) const {
  cmd.bindPipeline(::vk::PipelineBindPoint::eGraphics, *built_->pipeline);
  built_->layout.Push(cmd, ::vk::PipelineBindPoint::eGraphics, slots, push_constants, name_);
}

Rendering::Rendering(const CommandBuffer& cmd, const RenderTargets& targets) : cmd_(cmd) {
  const Image* sized = targets.colors.empty() ? targets.depth : targets.colors.front();
  if (!sized) throw Error("render targets", "none", "at least one color or depth image");
  std::vector<::vk::RenderingAttachmentInfo> colors;
  for (size_t i = 0; i < targets.colors.size(); ++i) {
    bool clear = i < targets.clear_colors.size() && targets.clear_colors[i].has_value();
    colors.push_back(::vk::RenderingAttachmentInfo{
        .imageView = targets.colors[i]->view(),
        .imageLayout = ::vk::ImageLayout::eGeneral,
        .loadOp = clear ? ::vk::AttachmentLoadOp::eClear : ::vk::AttachmentLoadOp::eLoad,
        .storeOp = ::vk::AttachmentStoreOp::eStore,
        .clearValue = ::vk::ClearValue{.color = ::vk::ClearColorValue{
            .float32 = clear ? *targets.clear_colors[i] : std::array<float, 4>{0, 0, 0, 0}}}});
  }
  ::vk::RenderingAttachmentInfo depth;
  if (targets.depth) {
    depth = ::vk::RenderingAttachmentInfo{
        .imageView = targets.depth->view(),
        .imageLayout = ::vk::ImageLayout::eGeneral,
        .loadOp = targets.clear_depth ? ::vk::AttachmentLoadOp::eClear : ::vk::AttachmentLoadOp::eLoad,
        .storeOp = ::vk::AttachmentStoreOp::eStore,
        .clearValue = ::vk::ClearValue{
            .depthStencil = ::vk::ClearDepthStencilValue{targets.clear_depth.value_or(0.0f), 0}}};
  }
  ::vk::Extent2D extent{sized->extent().width, sized->extent().height};
  cmd.beginRendering(::vk::RenderingInfo{.renderArea = {.extent = extent},
                                         .layerCount = 1,
                                         .colorAttachmentCount = uint32_t(colors.size()),
                                         .pColorAttachments = colors.data(),
                                         .pDepthAttachment = targets.depth ? &depth : nullptr});
  SetViewport(cmd, extent);
}

Rendering::~Rendering() { cmd_.endRendering(); }

void ClearDepth(const CommandBuffer& cmd, const ::vk::Rect2D& rect, float depth) {
  cmd.clearAttachments(::vk::ClearAttachment{.aspectMask = ::vk::ImageAspectFlagBits::eDepth,
                                             .clearValue = {.depthStencil = {depth, 0}}},
                       ::vk::ClearRect{.rect = rect, .baseArrayLayer = 0, .layerCount = 1});
}

void SetViewport(const CommandBuffer& cmd, ::vk::Extent2D extent, ::vk::Offset2D offset) {
  cmd.setViewport(0, ::vk::Viewport{.x = float(offset.x), .y = float(offset.y), .width = float(extent.width),
                                    .height = float(extent.height), .minDepth = 0.0f, .maxDepth = 1.0f});
  cmd.setScissor(0, ::vk::Rect2D{.offset = offset, .extent = extent});
}

void SetScissor(const CommandBuffer& cmd, const ::vk::Rect2D& rect) { cmd.setScissor(0, rect); }

void SetCullMode(const CommandBuffer& cmd, ::vk::CullModeFlags mode) { cmd.setCullMode(mode); }

void BindMesh(const CommandBuffer& cmd, const Buffer& vertices, const Buffer& indices) {
  cmd.bindVertexBuffers(0, vertices.handle(), ::vk::DeviceSize(0));
  cmd.bindIndexBuffer(indices.handle(), 0, ::vk::IndexType::eUint32);
}

void DrawIndexed(const CommandBuffer& cmd, uint32_t index_count, uint32_t first_index,
                 int32_t vertex_offset, uint32_t first_instance) {
  cmd.drawIndexed(index_count, 1, first_index, vertex_offset, first_instance);
}

void DrawGeneratedTriangle(const CommandBuffer& cmd) { cmd.draw(3, 1, 0, 0); }

}  // namespace aerial::vk
