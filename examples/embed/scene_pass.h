#pragma once
// The engine's own raster pass, recorded into its frame's command buffer after aerial's froxel
// build (aerial::Froxels::Record): dynamic rendering into an RGBA32F color target and a D32 depth
// target with reversed Z (cleared to 0, nearer is greater), drawing
//  - the scene's opaque meshes from the engine's own vertex and index buffers (shaders/mesh.*),
//    lit with aerial's tables and seen through aerial's froxel volume;
//  - then the sky where no mesh is, a full-screen triangle at depth 0 (shaders/sky.*);
// with the engine's own descriptor pool, sets and pipelines. It then copies the color target to
// a buffer the host reads once the frame is done.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan_core.h>

#include "aerial/froxels.h"
#include "aerial/scene.h"
#include "aerial/tables.h"
#include "gpu_memory.h"
#include "vulkan_setup.h"

class ScenePass {
 public:
  // Reads the tables' and the froxels' blocks and images once: their handles stay the same for
  // their lifetime, so the descriptor sets are written here and not per frame.
  ScenePass(const VulkanSetup& vulkan, const aerial::Scene& scene, const aerial::Tables& tables,
            const aerial::Froxels& froxels, uint32_t width, uint32_t height);
  ~ScenePass();
  ScenePass(const ScenePass&) = delete;
  ScenePass& operator=(const ScenePass&) = delete;

  void Record(VkCommandBuffer cmd) const;

  // Once the frame's commands are done: the color target, 4 floats per pixel, top row first
  // (rgb: radiance in W/m^2/sr/nm; a: the distance to the surface in m, infinite on the sky).
  std::vector<float> ReadBack() const;

 private:
  // One opaque mesh of the scene in the shared buffers.
  struct MeshDraw {
    uint32_t first_index = 0, index_count = 0;
    int32_t vertex_offset = 0;
    bool cull_back_faces = true;  // false for a double-sided mesh
  };

  void UploadMeshes(const aerial::Scene& scene);
  void CreateDescriptors(const aerial::Tables& tables, const aerial::Froxels& froxels);
  void CreatePipelines();
  void Release();  // destroys what was made, in reverse order

  const VulkanSetup& vulkan_;
  VkExtent2D extent_;
  Image color_, depth_;
  MappedBuffer read_back_;
  MappedBuffer vertices_, indices_;
  std::vector<MeshDraw> draws_;
  VkDescriptorSetLayout aerial_blocks_layout_ = VK_NULL_HANDLE, images_layout_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptor_pool_ = VK_NULL_HANDLE;
  VkDescriptorSet aerial_blocks_ = VK_NULL_HANDLE, images_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  VkPipeline mesh_pipeline_ = VK_NULL_HANDLE, sky_pipeline_ = VK_NULL_HANDLE;
};
