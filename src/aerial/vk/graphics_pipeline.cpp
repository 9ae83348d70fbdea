#include "aerial/vk/graphics_pipeline.h"

#include "aerial/core/error.h"

namespace aerial::vk {

GraphicsPipeline::GraphicsPipeline(const Context& context, const GraphicsPipelineCreateInfo& info)
    : name_(info.vertex_shader + "+" + info.fragment_shader),
      layout_(context, info.slot_types, info.push_constant_bytes,
              ::vk::ShaderStageFlagBits::eVertex | ::vk::ShaderStageFlagBits::eFragment) {
  ::vk::raii::ShaderModule vertex = CreateShaderModule(context, info.vertex_shader);
  ::vk::raii::ShaderModule fragment = CreateShaderModule(context, info.fragment_shader);
  std::vector<::vk::SpecializationMapEntry> entries;
  for (uint32_t i = 0; i < info.specialization.size(); ++i)
    entries.push_back({.constantID = i, .offset = uint32_t(i * sizeof(int32_t)), .size = sizeof(int32_t)});
  ::vk::SpecializationInfo specialization{.mapEntryCount = uint32_t(entries.size()),
                                          .pMapEntries = entries.data(),
                                          .dataSize = info.specialization.size() * sizeof(int32_t),
                                          .pData = info.specialization.data()};
  const ::vk::SpecializationInfo* constants = entries.empty() ? nullptr : &specialization;
  std::array<::vk::PipelineShaderStageCreateInfo, 2> stages = {
      ::vk::PipelineShaderStageCreateInfo{.stage = ::vk::ShaderStageFlagBits::eVertex,
                                          .module = *vertex, .pName = "main",
                                          .pSpecializationInfo = constants},
      ::vk::PipelineShaderStageCreateInfo{.stage = ::vk::ShaderStageFlagBits::eFragment,
                                          .module = *fragment, .pName = "main",
                                          .pSpecializationInfo = constants}};
  ::vk::VertexInputBindingDescription binding{.binding = 0, .stride = info.vertex_stride,
                                              .inputRate = ::vk::VertexInputRate::eVertex};
  std::vector<::vk::VertexInputAttributeDescription> attributes;
  for (uint32_t i = 0; i < info.attributes.size(); ++i)
    attributes.push_back({.location = i, .binding = 0, .format = info.attributes[i].format,
                          .offset = info.attributes[i].offset});
  ::vk::PipelineVertexInputStateCreateInfo vertex_input{
      .vertexBindingDescriptionCount = 1, .pVertexBindingDescriptions = &binding,
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
  std::vector<::vk::PipelineColorBlendAttachmentState> blends(info.color_formats.size(), blend);
  ::vk::PipelineColorBlendStateCreateInfo color_blend{.attachmentCount = uint32_t(blends.size()),
                                                      .pAttachments = blends.data()};
  std::array<::vk::DynamicState, 2> dynamic_states = {::vk::DynamicState::eViewport,
                                                      ::vk::DynamicState::eScissor};
  ::vk::PipelineDynamicStateCreateInfo dynamic{.dynamicStateCount = 2, .pDynamicStates = dynamic_states.data()};
  ::vk::PipelineRenderingCreateInfo rendering{
      .colorAttachmentCount = uint32_t(info.color_formats.size()),
      .pColorAttachmentFormats = info.color_formats.data(),
      .depthAttachmentFormat = info.depth_format.value_or(::vk::Format::eUndefined)};
  pipeline_ = ::vk::raii::Pipeline(
      context.device(), nullptr,
      ::vk::GraphicsPipelineCreateInfo{.pNext = &rendering,
                                       .stageCount = 2,
                                       .pStages = stages.data(),
                                       .pVertexInputState = &vertex_input,
                                       .pInputAssemblyState = &assembly,
                                       .pViewportState = &viewport,
                                       .pRasterizationState = &raster,
                                       .pMultisampleState = &multisample,
                                       .pDepthStencilState = &depth,
                                       .pColorBlendState = &color_blend,
                                       .pDynamicState = &dynamic,
                                       .layout = *layout_.layout});
}

void GraphicsPipeline::Draw(const ::vk::raii::CommandBuffer& cmd, const RenderTargets& targets,
                            const std::vector<Slot>& slots, const Buffer& vertices,
                            const Buffer& indices, uint32_t index_count,
                            const void* push_constants) const {
  if (targets.colors.empty()) throw Error(name_ + " color targets", "0", "at least one");
  ::vk::Extent3D extent = targets.colors.front()->extent();
  std::vector<::vk::RenderingAttachmentInfo> colors;
  for (size_t i = 0; i < targets.colors.size(); ++i) {
    bool clear = i < targets.clear_colors.size() && targets.clear_colors[i].has_value();
    colors.push_back(::vk::RenderingAttachmentInfo{
        .imageView = targets.colors[i]->view(),
        .imageLayout = ::vk::ImageLayout::eGeneral,
        .loadOp = clear ? ::vk::AttachmentLoadOp::eClear : ::vk::AttachmentLoadOp::eLoad,
        .storeOp = ::vk::AttachmentStoreOp::eStore,
        .clearValue = ::vk::ClearValue{.color = ::vk::ClearColorValue(
            clear ? *targets.clear_colors[i] : std::array<float, 4>{0, 0, 0, 0})}});
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
  ::vk::Rect2D area{.extent = {extent.width, extent.height}};
  cmd.beginRendering(::vk::RenderingInfo{.renderArea = area,
                                         .layerCount = 1,
                                         .colorAttachmentCount = uint32_t(colors.size()),
                                         .pColorAttachments = colors.data(),
                                         .pDepthAttachment = targets.depth ? &depth : nullptr});
  cmd.bindPipeline(::vk::PipelineBindPoint::eGraphics, *pipeline_);
  layout_.Push(cmd, ::vk::PipelineBindPoint::eGraphics, slots, push_constants, name_);
  cmd.setViewport(0, ::vk::Viewport{.width = float(extent.width), .height = float(extent.height),
                                    .minDepth = 0.0f, .maxDepth = 1.0f});
  cmd.setScissor(0, area);
  cmd.bindVertexBuffers(0, vertices.handle(), ::vk::DeviceSize(0));
  cmd.bindIndexBuffer(indices.handle(), 0, ::vk::IndexType::eUint32);
  cmd.drawIndexed(index_count, 1, 0, 0, 0);
  cmd.endRendering();
}

}  // namespace aerial::vk
