#pragma once
// The engine's own Vulkan objects, which it hands to aerial (aerial::DeviceHandoff): an instance
// (with the Khronos validation layers and a debug messenger that counts their messages when
// asked), a physical device, a Vulkan 1.3 device made with what aerial requires
// (aerial::RequiredDeviceFeatures, aerial::kRequiredDeviceExtensions), one queue that draws,
// computes and times, a command pool with the frame's command buffer, and the frame's fence.
// aerial destroys none of them; this class does, last, once aerial's objects are gone.
#include <cstdint>

#include <vulkan/vulkan_core.h>

#include "aerial/device.h"

// Throws std::runtime_error naming the call when a Vulkan call did not succeed.
void Check(VkResult result, const char* call);

// Validation messages (warnings and errors) counted so far, from the instance's creation on.
int ValidationMessageCount();

struct VulkanSetup {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;  // with validation only
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkPhysicalDeviceMemoryProperties memory{};
  uint32_t queue_family = 0;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  VkCommandPool command_pool = VK_NULL_HANDLE;
  VkCommandBuffer command_buffer = VK_NULL_HANDLE;  // the frame's
  VkFence frame_done = VK_NULL_HANDLE;

  explicit VulkanSetup(bool validation);
  ~VulkanSetup();  // waits for the device, then destroys everything above in reverse order
  VulkanSetup(const VulkanSetup&) = delete;
  VulkanSetup& operator=(const VulkanSetup&) = delete;

  aerial::DeviceHandoff Handoff() const;
  // Submits the frame's command buffer to the queue and waits for its fence.
  void SubmitFrameAndWait() const;

 private:
  void Destroy();
};
