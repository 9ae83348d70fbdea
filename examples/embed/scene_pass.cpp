// The engine's raster pass (scene_pass.h), with Vulkan's C API.
#include "scene_pass.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

// The example's shaders, compiled at build time against aerial's installed GLSL (CMakeLists.txt).
#include "shaders/mesh_frag.h"
#include "shaders/mesh_vert.h"
#include "shaders/sky_frag.h"
#include "shaders/sky_vert.h"

namespace {

constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

// The engine's vertex: aerial::Vertex without the opacity that only transparent meshes use.
struct MeshVertex {
  float position[3];  // world frame of aerial/scene.h, m
  float normal[3];
  float albedo[3];
};

VkShaderModule CreateShaderModule(VkDevice device, std::span<const uint32_t> spirv) {
  VkShaderModuleCreateInfo info{.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                .codeSize = spirv.size_bytes(),
                                .pCode = spirv.data()};
  VkShaderModule module = VK_NULL_HANDLE;
  Check(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule");
  return module;
}

// What differs between the mesh and the sky pipelines.
struct PipelineInfo {
  std::span<const uint32_t> vertex_spirv, fragment_spirv;
  const VkPipelineVertexInputStateCreateInfo* vertex_input;
  bool depth_write;
  VkCompareOp depth_compare;
  bool dynamic_cull_mode;  // set per draw; otherwise nothing is culled
};

VkPipeline CreatePipeline(VkDevice device, VkPipelineLayout layout, const PipelineInfo& info) {
  VkShaderModule vertex = CreateShaderModule(device, info.vertex_spirv);
  VkShaderModule fragment = CreateShaderModule(device, info.fragment_spirv);
  std::array<VkPipelineShaderStageCreateInfo, 2> stages = {
      VkPipelineShaderStageCreateInfo{.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                                      .stage = VK_SHADER_STAGE_VERTEX_BIT, .module = vertex, .pName = "main"},
      VkPipelineShaderStageCreateInfo{.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                                      .stage = VK_SHADER_STAGE_FRAGMENT_BIT, .module = fragment, .pName = "main"}};
  VkPipelineInputAssemblyStateCreateInfo assembly{.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
                                                  .topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST};
  VkPipelineViewportStateCreateInfo viewport{.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
                                             .viewportCount = 1, .scissorCount = 1};
  // Triangles wind counter-clockwise seen from their front (aerial/scene.h). aerial's projection
  // flips y (its clip space is Vulkan's, y down), so the image is upright and a front face still
  // winds counter-clockwise on the screen: front faces are counter-clockwise, as in aerial's own
  // pipelines.
  VkPipelineRasterizationStateCreateInfo raster{.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
                                                .polygonMode = VK_POLYGON_MODE_FILL,
                                                .cullMode = VK_CULL_MODE_NONE,
                                                .frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE,
                                                .lineWidth = 1.0f};
  VkPipelineMultisampleStateCreateInfo multisample{.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
                                                   .rasterizationSamples = VK_SAMPLE_COUNT_1_BIT};
  VkPipelineDepthStencilStateCreateInfo depth{.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
                                              .depthTestEnable = VK_TRUE,
                                              .depthWriteEnable = info.depth_write ? VK_TRUE : VK_FALSE,
                                              .depthCompareOp = info.depth_compare};
  VkPipelineColorBlendAttachmentState blend{.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                                              VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT};
  VkPipelineColorBlendStateCreateInfo color_blend{.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
                                                  .attachmentCount = 1, .pAttachments = &blend};
  std::array<VkDynamicState, 3> dynamic_states = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                                  VK_DYNAMIC_STATE_CULL_MODE};
  VkPipelineDynamicStateCreateInfo dynamic{.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
                                           .dynamicStateCount = info.dynamic_cull_mode ? 3u : 2u,
                                           .pDynamicStates = dynamic_states.data()};
  // Dynamic rendering (core in Vulkan 1.3): the attachments' formats instead of a render pass.
  VkPipelineRenderingCreateInfo rendering{.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
                                          .colorAttachmentCount = 1,
                                          .pColorAttachmentFormats = &kColorFormat,
                                          .depthAttachmentFormat = kDepthFormat};
  VkGraphicsPipelineCreateInfo pipeline_info{.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
                                             .pNext = &rendering,
                                             .stageCount = uint32_t(stages.size()),
                                             .pStages = stages.data(),
                                             .pVertexInputState = info.vertex_input,
                                             .pInputAssemblyState = &assembly,
                                             .pViewportState = &viewport,
                                             .pRasterizationState = &raster,
                                             .pMultisampleState = &multisample,
                                             .pDepthStencilState = &depth,
                                             .pColorBlendState = &color_blend,
                                             .pDynamicState = &dynamic,
                                             .layout = layout};
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkResult result = vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, &pipeline);
  vkDestroyShaderModule(device, vertex, nullptr);
  vkDestroyShaderModule(device, fragment, nullptr);
  Check(result, "vkCreateGraphicsPipelines");
  return pipeline;
}

VkImageMemoryBarrier ImageBarrier(VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
                                  VkAccessFlags src_access, VkAccessFlags dst_access) {
  return {.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
          .srcAccessMask = src_access,
          .dstAccessMask = dst_access,
          .oldLayout = from,
          .newLayout = to,
          .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
          .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
          .image = image,
          .subresourceRange = {.aspectMask = aspect, .levelCount = 1, .layerCount = 1}};
}

}  // namespace

ScenePass::ScenePass(const VulkanSetup& vulkan, const aerial::Scene& scene, const aerial::Tables& tables,
                     const aerial::Froxels& froxels, uint32_t width, uint32_t height)
    : vulkan_(vulkan), extent_{width, height} {
  try {
    color_ = CreateImage(vulkan, extent_, kColorFormat,
                         VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                         VK_IMAGE_ASPECT_COLOR_BIT);
    depth_ = CreateImage(vulkan, extent_, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                         VK_IMAGE_ASPECT_DEPTH_BIT);
    read_back_ = CreateMappedBuffer(vulkan, VkDeviceSize(width) * height * 4 * sizeof(float),
                                    VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    UploadMeshes(scene);
    CreateDescriptors(tables, froxels);
    CreatePipelines();
  } catch (...) {
    Release();  // a constructor that throws runs no destructor
    throw;
  }
}

ScenePass::~ScenePass() { Release(); }

void ScenePass::Release() {
  VkDevice device = vulkan_.device;
  vkDestroyPipeline(device, sky_pipeline_, nullptr);
  vkDestroyPipeline(device, mesh_pipeline_, nullptr);
  vkDestroyPipelineLayout(device, pipeline_layout_, nullptr);
  vkDestroyDescriptorPool(device, descriptor_pool_, nullptr);  // frees the sets
  vkDestroyDescriptorSetLayout(device, images_layout_, nullptr);
  vkDestroyDescriptorSetLayout(device, aerial_blocks_layout_, nullptr);
  Destroy(device, indices_);
  Destroy(device, vertices_);
  Destroy(device, read_back_);
  Destroy(device, depth_);
  Destroy(device, color_);
}

// The opaque meshes, one after the other in one vertex and one index buffer, one draw each.
// Transparent meshes would be blended after the sky; this example leaves them out.
void ScenePass::UploadMeshes(const aerial::Scene& scene) {
  std::vector<MeshVertex> vertices;
  std::vector<uint32_t> indices;
  for (const aerial::Mesh& mesh : scene.meshes) {
    if (mesh.transparent) continue;
    draws_.push_back({.first_index = uint32_t(indices.size()),
                      .index_count = uint32_t(mesh.indices.size()),
                      .vertex_offset = int32_t(vertices.size()),
                      .cull_back_faces = !mesh.double_sided});
    for (const aerial::Vertex& v : mesh.vertices) {
      vertices.push_back({{v.position.x, v.position.y, v.position.z},
                          {v.normal.x, v.normal.y, v.normal.z},
                          {v.albedo.x, v.albedo.y, v.albedo.z}});
    }
    indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
  }
  // Never empty: a scene without opaque meshes still binds a buffer (and draws nothing).
  vertices_ = CreateMappedBuffer(vulkan_, std::max<size_t>(1, vertices.size()) * sizeof(MeshVertex),
                                 VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  indices_ = CreateMappedBuffer(vulkan_, std::max<size_t>(1, indices.size()) * sizeof(uint32_t),
                                VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  if (draws_.empty()) return;
  std::memcpy(vertices_.data, vertices.data(), vertices.size() * sizeof(MeshVertex));
  std::memcpy(indices_.data, indices.data(), indices.size() * sizeof(uint32_t));
}

// Set 0: aerial's uniform blocks at the bindings its GLSL declares them at. Set 1: the tables and
// the froxel volume, at the engine's own bindings (shaders/bindings.glsl), each image with the
// sampler aerial made for it and in the layout it stays in (GENERAL).
void ScenePass::CreateDescriptors(const aerial::Tables& tables, const aerial::Froxels& froxels) {
  const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
  const std::array<aerial::UniformBlock, 2> blocks = {tables.atmosphere_block(), froxels.frame_block()};
  const std::array<aerial::SampledImage, 8> images = {tables.transmittance(), tables.irradiance(),
                                                      tables.rayleigh(),      tables.mie(),
                                                      tables.multiple(),      froxels.rayleigh(),
                                                      froxels.mie(),          froxels.transmittance()};

  std::vector<VkDescriptorSetLayoutBinding> block_bindings(blocks.size());
  for (uint32_t i = 0; i < block_bindings.size(); ++i)
    block_bindings[i] = {.binding = i, .descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                         .descriptorCount = 1, .stageFlags = stages};
  std::vector<VkDescriptorSetLayoutBinding> image_bindings(images.size());
  for (uint32_t i = 0; i < image_bindings.size(); ++i)
    image_bindings[i] = {.binding = i, .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                         .descriptorCount = 1, .stageFlags = stages};
  VkDescriptorSetLayoutCreateInfo blocks_info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                              .bindingCount = uint32_t(block_bindings.size()),
                                              .pBindings = block_bindings.data()};
  Check(vkCreateDescriptorSetLayout(vulkan_.device, &blocks_info, nullptr, &aerial_blocks_layout_),
        "vkCreateDescriptorSetLayout");
  VkDescriptorSetLayoutCreateInfo images_info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                              .bindingCount = uint32_t(image_bindings.size()),
                                              .pBindings = image_bindings.data()};
  Check(vkCreateDescriptorSetLayout(vulkan_.device, &images_info, nullptr, &images_layout_),
        "vkCreateDescriptorSetLayout");

  std::array<VkDescriptorPoolSize, 2> sizes = {
      VkDescriptorPoolSize{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, uint32_t(blocks.size())},
      VkDescriptorPoolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, uint32_t(images.size())}};
  VkDescriptorPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                       .maxSets = 2,
                                       .poolSizeCount = uint32_t(sizes.size()),
                                       .pPoolSizes = sizes.data()};
  Check(vkCreateDescriptorPool(vulkan_.device, &pool_info, nullptr, &descriptor_pool_), "vkCreateDescriptorPool");
  std::array<VkDescriptorSetLayout, 2> layouts = {aerial_blocks_layout_, images_layout_};
  VkDescriptorSetAllocateInfo allocate{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                       .descriptorPool = descriptor_pool_,
                                       .descriptorSetCount = uint32_t(layouts.size()),
                                       .pSetLayouts = layouts.data()};
  std::array<VkDescriptorSet, 2> sets;
  Check(vkAllocateDescriptorSets(vulkan_.device, &allocate, sets.data()), "vkAllocateDescriptorSets");
  aerial_blocks_ = sets[0];
  images_ = sets[1];

  std::vector<VkDescriptorBufferInfo> buffer_infos(blocks.size());
  std::vector<VkDescriptorImageInfo> image_infos(images.size());
  std::vector<VkWriteDescriptorSet> writes;
  for (uint32_t i = 0; i < blocks.size(); ++i) {
    buffer_infos[i] = {.buffer = blocks[i].buffer, .offset = 0, .range = blocks[i].size};
    writes.push_back({.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, .dstSet = aerial_blocks_, .dstBinding = i,
                      .descriptorCount = 1, .descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                      .pBufferInfo = &buffer_infos[i]});
  }
  for (uint32_t i = 0; i < images.size(); ++i) {
    image_infos[i] = {.sampler = images[i].sampler, .imageView = images[i].view, .imageLayout = images[i].layout};
    writes.push_back({.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, .dstSet = images_, .dstBinding = i,
                      .descriptorCount = 1, .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                      .pImageInfo = &image_infos[i]});
  }
  vkUpdateDescriptorSets(vulkan_.device, uint32_t(writes.size()), writes.data(), 0, nullptr);
}

void ScenePass::CreatePipelines() {
  std::array<VkDescriptorSetLayout, 2> set_layouts = {aerial_blocks_layout_, images_layout_};
  VkPipelineLayoutCreateInfo layout_info{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                         .setLayoutCount = uint32_t(set_layouts.size()),
                                         .pSetLayouts = set_layouts.data()};
  Check(vkCreatePipelineLayout(vulkan_.device, &layout_info, nullptr, &pipeline_layout_), "vkCreatePipelineLayout");

  VkVertexInputBindingDescription binding{.binding = 0, .stride = sizeof(MeshVertex),
                                          .inputRate = VK_VERTEX_INPUT_RATE_VERTEX};
  std::array<VkVertexInputAttributeDescription, 3> attributes = {
      VkVertexInputAttributeDescription{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(MeshVertex, position)},
      VkVertexInputAttributeDescription{1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(MeshVertex, normal)},
      VkVertexInputAttributeDescription{2, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(MeshVertex, albedo)}};
  VkPipelineVertexInputStateCreateInfo mesh_input{.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
                                                  .vertexBindingDescriptionCount = 1,
                                                  .pVertexBindingDescriptions = &binding,
                                                  .vertexAttributeDescriptionCount = uint32_t(attributes.size()),
                                                  .pVertexAttributeDescriptions = attributes.data()};
  VkPipelineVertexInputStateCreateInfo no_input{.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  // Reversed Z: the nearer surface has the greater depth.
  mesh_pipeline_ = CreatePipeline(vulkan_.device, pipeline_layout_,
                                  {.vertex_spirv = mesh_vert_spirv, .fragment_spirv = mesh_frag_spirv,
                                   .vertex_input = &mesh_input, .depth_write = true,
                                   .depth_compare = VK_COMPARE_OP_GREATER, .dynamic_cull_mode = true});
  // At depth 0, it passes only where the depth is still the cleared 0: where no mesh was drawn.
  sky_pipeline_ = CreatePipeline(vulkan_.device, pipeline_layout_,
                                 {.vertex_spirv = sky_vert_spirv, .fragment_spirv = sky_frag_spirv,
                                  .vertex_input = &no_input, .depth_write = false,
                                  .depth_compare = VK_COMPARE_OP_GREATER_OR_EQUAL, .dynamic_cull_mode = false});
}

void ScenePass::Record(VkCommandBuffer cmd) const {
  // The targets' previous contents are not needed: from UNDEFINED to attachments.
  std::array<VkImageMemoryBarrier, 2> to_attachments = {
      ImageBarrier(color_.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, 0, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT),
      ImageBarrier(depth_.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, 0,
                   VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT)};
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                       VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                           VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                       0, 0, nullptr, 0, nullptr, uint32_t(to_attachments.size()), to_attachments.data());

  VkRenderingAttachmentInfo color{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                  .imageView = color_.view,
                                  .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                  .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                  .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                  .clearValue = {.color = {.float32 = {0, 0, 0, 0}}}};
  VkRenderingAttachmentInfo depth{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                  .imageView = depth_.view,
                                  .imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                                  .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                  .storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
                                  .clearValue = {.depthStencil = {.depth = 0.0f}}};  // reversed Z: infinitely far
  VkRenderingInfo rendering{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                            .renderArea = {.extent = extent_},
                            .layerCount = 1,
                            .colorAttachmentCount = 1,
                            .pColorAttachments = &color,
                            .pDepthAttachment = &depth};
  vkCmdBeginRendering(cmd, &rendering);
  VkViewport viewport{.width = float(extent_.width), .height = float(extent_.height), .maxDepth = 1.0f};
  VkRect2D scissor{.extent = extent_};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  std::array<VkDescriptorSet, 2> sets = {aerial_blocks_, images_};
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_layout_, 0, uint32_t(sets.size()),
                          sets.data(), 0, nullptr);

  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mesh_pipeline_);
  VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertices_.buffer, &offset);
  vkCmdBindIndexBuffer(cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
  for (const MeshDraw& draw : draws_) {
    vkCmdSetCullMode(cmd, draw.cull_back_faces ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE);
    vkCmdDrawIndexed(cmd, draw.index_count, 1, draw.first_index, draw.vertex_offset, 0);
  }

  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, sky_pipeline_);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  vkCmdEndRendering(cmd);

  // The color target to the read-back buffer, then visible to the host.
  VkImageMemoryBarrier to_transfer =
      ImageBarrier(color_.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                   VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                   VK_ACCESS_TRANSFER_READ_BIT);
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                       nullptr, 0, nullptr, 1, &to_transfer);
  VkBufferImageCopy copy{.imageSubresource = {.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT, .layerCount = 1},
                         .imageExtent = {extent_.width, extent_.height, 1}};
  vkCmdCopyImageToBuffer(cmd, color_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, read_back_.buffer, 1, &copy);
  VkBufferMemoryBarrier to_host{.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER,
                                .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                                .dstAccessMask = VK_ACCESS_HOST_READ_BIT,
                                .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                .buffer = read_back_.buffer,
                                .size = VK_WHOLE_SIZE};
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &to_host,
                       0, nullptr);
}

std::vector<float> ScenePass::ReadBack() const {
  const float* texels = static_cast<const float*>(read_back_.data);
  return std::vector<float>(texels, texels + size_t(extent_.width) * extent_.height * 4);
}
