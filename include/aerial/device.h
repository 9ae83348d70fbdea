#pragma once
// The Vulkan device aerial works on: one it creates itself, or the caller's own (a renderer that
// embeds aerial). This header and tables.h / froxels.h use Vulkan's C API only, so a caller's
// build settings (NDEBUG, vulkan.hpp's options) need not match aerial's.
//
// On the caller's device aerial makes its own command pool, fence and resources, submits one-off
// work (uploads, the precompute, read-backs) to the given queue and waits for it; the caller must
// not use that queue from another thread meanwhile. Frames are recorded into the caller's command
// buffers (Froxels::Record), which the caller submits: aerial never waits inside a frame. aerial
// destroys neither the device nor the instance, also when a check fails.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <vulkan/vulkan_core.h>

namespace aerial {

// The caller's device, made for Vulkan 1.3 with kRequiredDeviceExtensions and
// RequiredDeviceFeatures enabled. aerial checks the version, the queue family (graphics, compute
// and timestamps) and the extensions; which features were enabled it cannot see.
struct DeviceHandoff {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queue_family = 0;
  uint32_t queue_index = 0;
  // The device was made with the optional feature pipelineStatisticsQuery: passes then count their
  // fragment-shader invocations (PassTime).
  bool pipeline_statistics = false;
};

// The device extensions aerial uses: descriptors are pushed, not allocated from pools; draws are
// made conditional on a value the GPU wrote (a shadow map's tile redrawn only where the casters
// the GPU selected changed).
inline constexpr std::array<const char*, 2> kRequiredDeviceExtensions = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME,
                                                                         VK_EXT_CONDITIONAL_RENDERING_EXTENSION_NAME};

// The device features aerial uses: storage images written without a format in the shader (the
// precompute), indirect draws of many commands each with its own first instance, their count read
// from a buffer (the terrain's chunks, selected on the CPU or the GPU), dynamic rendering (raster
// passes), host query reset (GPU timers) and conditional rendering.
struct RequiredDeviceFeatures {
  VkPhysicalDeviceFeatures core{.multiDrawIndirect = VK_TRUE,
                                .drawIndirectFirstInstance = VK_TRUE,
                                .shaderStorageImageWriteWithoutFormat = VK_TRUE};
  VkPhysicalDeviceVulkan12Features vulkan12{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                            .drawIndirectCount = VK_TRUE,
                                            .hostQueryReset = VK_TRUE};
  VkPhysicalDeviceVulkan13Features vulkan13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
                                            .dynamicRendering = VK_TRUE};
  VkPhysicalDeviceConditionalRenderingFeaturesEXT conditional_rendering{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_CONDITIONAL_RENDERING_FEATURES_EXT, .conditionalRendering = VK_TRUE};
  // The chain for VkDeviceCreateInfo::pNext, with pEnabledFeatures = &core; next: the caller's
  // own chain, placed after it. Valid while this object lives and stays where it is.
  void* Chain(void* next = nullptr) {
    conditional_rendering.pNext = next;
    vulkan13.pNext = &conditional_rendering;
    vulkan12.pNext = &vulkan13;
    return &vulkan12;
  }
};

// The GPU time of one pass of aerial's (a precompute pass, a pass of a frame), from the device's
// timestamps.
struct PassTime {
  std::string pass;
  double milliseconds = 0.0;
  // Fragment-shader invocations of the pass, where the device counts them
  // (DeviceHandoff::pipeline_statistics; aerial's own device enables it where it exists).
  std::optional<uint64_t> fragment_shader_invocations;
};

// aerial's own device.
struct DeviceOptions {
  std::string device_name;  // substring of the device's name (any case); empty: $AERIAL_DEVICE or the best
  bool validation = false;  // Khronos validation layers; also on with AERIAL_VALIDATION=1
};

class Device {
 public:
  // aerial creates an instance and a device of its own.
  explicit Device(const DeviceOptions& options = {});
  // aerial works on the caller's device. Throws aerial::Error for null handles, a Vulkan version
  // below 1.3, a queue family that cannot draw, compute and time, or a missing extension.
  explicit Device(const DeviceHandoff& handoff);
  ~Device();
  Device(Device&&) noexcept;
  Device& operator=(Device&&) noexcept;

  std::string name() const;
  bool validation_enabled() const;
  // The size of the device's largest device-local memory heap, in bytes.
  uint64_t largest_heap_bytes() const;
  // Validation messages (warnings and errors) seen so far by every device aerial created itself.
  static int ValidationMessageCount();

  struct Impl;  // aerial's side (src/aerial/api/impl.h)

 private:
  friend struct ImplAccess;  // aerial's own code (src/aerial/api/impl.h)
  std::unique_ptr<Impl> impl_;
};

}  // namespace aerial
