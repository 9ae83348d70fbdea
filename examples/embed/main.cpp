// How a renderer embeds aerial. The engine makes its own Vulkan instance, device, queue and
// command pool (vulkan_setup.h) and hands them to aerial, which loads or precomputes the Earth
// atmosphere's tables on that device. Each frame aerial records the froxel volume into the
// engine's command buffer; the engine then draws its own meshes and the sky with its own
// pipelines and shaders, which include aerial's GLSL (scene_pass.h), submits the command buffer
// and waits on its own fence. The frame goes to an EXR file (exr_io.h).
//   embed SCENE.toml OUT.exr CACHE_DIR [WIDTH HEIGHT]
// With AERIAL_VALIDATION=1 the Khronos validation layers watch the whole run; any message they
// give fails it.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "aerial/aerial.h"
#include "exr_io.h"
#include "scene_pass.h"
#include "vulkan_setup.h"

namespace {

bool ValidationWanted() {
  const char* value = std::getenv("AERIAL_VALIDATION");
  return value != nullptr && std::string_view(value) == "1";
}

void RenderFrame(const VulkanSetup& vulkan, const std::filesystem::path& scene_file,
                 const std::filesystem::path& out, const std::filesystem::path& cache_dir, uint32_t width,
                 uint32_t height) {
  aerial::Device device(vulkan.Handoff());
  std::printf("aerial %s on %s\n", AERIAL_VERSION, device.name().c_str());
  aerial::AtmosphereParameters earth = aerial::AtmosphereParameters::Earth();
  aerial::TableLoadOptions load{.cache_dir = cache_dir, .progress = [](int done, int total, std::string_view pass) {
                                  std::printf("precompute %d/%d: %.*s\n", done, total, int(pass.size()), pass.data());
                                }};
  aerial::Tables tables =
      aerial::Tables::LoadOrPrecompute(device, earth, aerial::PrecomputeOptions::Default(), load);
  std::printf("tables %s %s\n", tables.from_cache() ? "read from" : "precomputed into",
              tables.cache_file().c_str());

  aerial::Scene scene = aerial::LoadSceneFile(scene_file, earth.bottom_radius_m);
  for (const aerial::Mesh& mesh : scene.meshes)
    if (mesh.transparent) std::printf("left out: the transparent mesh %s\n", mesh.name.c_str());
  aerial::FrameCamera camera = aerial::MakeFrameCamera(scene, width, height);
  aerial::Froxels froxels(device);  // the default grid: 32x32x32, quadratic to 128 km
  ScenePass pass(vulkan, scene, tables, froxels, width, height);

  // The frame, in the engine's command buffer: aerial's froxel volume (it ends with a barrier
  // that makes the volume and the FrameBlock readable by later shaders), then the engine's pass.
  VkCommandBuffer cmd = vulkan.command_buffer;
  VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                 .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  Check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  froxels.Record(cmd, tables, camera);
  pass.Record(cmd);
  Check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  vulkan.SubmitFrameAndWait();

  WriteExr(out, {.width = int(width), .height = int(height), .rgbd = pass.ReadBack()});
  std::printf("wrote %s (%ux%u)\n", out.c_str(), width, height);
}  // the pass goes first (its descriptor sets name aerial's images), then aerial's objects

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 && argc != 6) {
    std::fprintf(stderr, "usage: embed SCENE.toml OUT.exr CACHE_DIR [WIDTH HEIGHT]\n");
    return 2;
  }
  try {
    uint32_t width = argc == 6 ? uint32_t(std::stoul(argv[4])) : 1280;
    uint32_t height = argc == 6 ? uint32_t(std::stoul(argv[5])) : 720;
    if (width == 0 || height == 0) throw std::invalid_argument("WIDTH and HEIGHT must be at least 1");
    {
      VulkanSetup vulkan(ValidationWanted());
      RenderFrame(vulkan, argv[1], argv[2], argv[3], width, height);
    }  // the engine's device and instance go last, after aerial's objects
    int messages = ValidationMessageCount();
    std::printf("validation messages: %d\n", messages);
    return messages == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "embed: %s\n", e.what());
    return 1;
  }
}
