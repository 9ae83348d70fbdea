#include "own_device.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan_raii.hpp>

#include "aerial/precompute/table_store.h"
#include "aerial/render/renderer.h"
#include "aerial/scene/presets.h"
#include "aerial/vk/context.h"

namespace {

std::atomic<int> g_messages{0};

VKAPI_ATTR VkBool32 VKAPI_CALL CountMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                            VkDebugUtilsMessageTypeFlagsEXT,
                                            const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
  ++g_messages;
  std::fprintf(stderr, "client's validation: %s\n", data->pMessage);
  return VK_FALSE;
}

bool ValidationWanted() {
  const char* value = std::getenv("AERIAL_VALIDATION");
  return value != nullptr && std::string(value) == "1";
}

uint32_t GraphicsComputeFamily(const vk::raii::PhysicalDevice& device) {
  auto families = device.getQueueFamilyProperties();
  auto wanted = vk::QueueFlagBits::eGraphics | vk::QueueFlagBits::eCompute;
  for (uint32_t i = 0; i < families.size(); ++i)
    if ((families[i].queueFlags & wanted) == wanted) return i;
  throw std::runtime_error("no graphics+compute queue");
}

size_t DifferentPixels(const aerial::ImageRgbF& a, const aerial::ImageRgbF& b) {
  if (a.rgba.size() != b.rgba.size()) return a.rgba.size() / 4 + 1;
  size_t different = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4) different += !std::equal(&a.rgba[i], &a.rgba[i] + 4, &b.rgba[i]);
  return different;
}

}  // namespace

bool RunOnOwnDevice(const aerial::AtmosphereParameters& atmosphere, const std::filesystem::path& cache_dir) {
  bool validation = ValidationWanted();
  vk::raii::Context loader;
  std::vector<const char*> layers, extensions;
  if (validation) {
    layers.push_back("VK_LAYER_KHRONOS_validation");
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  vk::ApplicationInfo app{.pApplicationName = "package_client", .apiVersion = VK_API_VERSION_1_3};
  vk::raii::Instance instance(loader, vk::InstanceCreateInfo{.pApplicationInfo = &app,
                                                             .enabledLayerCount = uint32_t(layers.size()),
                                                             .ppEnabledLayerNames = layers.data(),
                                                             .enabledExtensionCount = uint32_t(extensions.size()),
                                                             .ppEnabledExtensionNames = extensions.data()});
  std::optional<vk::raii::DebugUtilsMessengerEXT> messenger;
  if (validation) {
    using Severity = vk::DebugUtilsMessageSeverityFlagBitsEXT;
    using Type = vk::DebugUtilsMessageTypeFlagBitsEXT;
    messenger.emplace(instance, vk::DebugUtilsMessengerCreateInfoEXT{
                                    .messageSeverity = Severity::eWarning | Severity::eError,
                                    .messageType = Type::eGeneral | Type::eValidation,
                                    .pfnUserCallback = &CountMessage});
  }
  vk::raii::PhysicalDevice physical = std::move(vk::raii::PhysicalDevices(instance).front());
  uint32_t family = GraphicsComputeFamily(physical);
  float priority = 1.0f;
  vk::DeviceQueueCreateInfo queue_info{.queueFamilyIndex = family, .queueCount = 1, .pQueuePriorities = &priority};
  aerial::vk::RequiredDeviceFeatures features;
  vk::raii::Device device(physical, vk::DeviceCreateInfo{
                                        .pNext = features.Chain(),
                                        .queueCreateInfoCount = 1,
                                        .pQueueCreateInfos = &queue_info,
                                        .enabledExtensionCount = uint32_t(aerial::vk::kRequiredDeviceExtensions.size()),
                                        .ppEnabledExtensionNames = aerial::vk::kRequiredDeviceExtensions.data(),
                                        .pEnabledFeatures = &features.core});
  vk::raii::Queue queue = device.getQueue(family, 0);
  vk::raii::CommandPool pool(device, vk::CommandPoolCreateInfo{.queueFamilyIndex = family});
  vk::raii::CommandBuffer cmd = std::move(vk::raii::CommandBuffers(
      device, vk::CommandBufferAllocateInfo{.commandPool = *pool, .commandBufferCount = 1}).front());
  vk::raii::Fence done(device, vk::FenceCreateInfo{});

  size_t different = 0;
  {
    aerial::vk::Context context(aerial::vk::ExternalDevice{
        .instance = *instance, .physical_device = *physical, .device = *device, .queue_family = family});
    aerial::LoadedTables loaded = aerial::LoadOrPrecompute(context, atmosphere, aerial::PrecomputeOptions::Small(),
                                                           {.cache_dir = cache_dir, .quiet = true});
    aerial::Scene scene = aerial::BuildPreset("noon", atmosphere.bottom_radius_m);
    aerial::RenderOptions options{.width = 96, .height = 54};
    // The client's frame: recorded into its command buffer, submitted to its queue, waited on.
    aerial::Renderer renderer(*loaded.tables, scene, options);
    cmd.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
    renderer.Record(cmd, scene, 0, /*complete=*/true);
    cmd.end();
    vk::CommandBuffer raw = *cmd;
    queue.submit(vk::SubmitInfo{.commandBufferCount = 1, .pCommandBuffers = &raw}, *done);
    if (device.waitForFences(*done, VK_TRUE, UINT64_MAX) != vk::Result::eSuccess) return false;
    aerial::ImageRgbF client_frame = renderer.ReadOutput();
    // The same frame as aerial submits it on its own.
    aerial::Renderer own(*loaded.tables, scene, options);
    own.Render(scene);
    different = DifferentPixels(client_frame, own.ReadOutput());
    std::printf("frame submitted by the client: %zu of %d pixels differ from aerial's own submit\n", different,
                options.width * options.height);
  }
  // aerial's objects are gone and the device is still the client's: destroying it here makes the
  // validation layers report anything aerial left on it.
  device.waitIdle();
  cmd.clear();
  pool.clear();
  done.clear();
  device.clear();
  std::printf("client's validation messages: %d\n", g_messages.load());
  return different == 0 && g_messages.load() == 0;
}
