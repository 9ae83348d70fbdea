// The engine's instance, device, queue, command pool and frame (vulkan_setup.h), with Vulkan's C
// API as the public aerial headers use it.
#include "vulkan_setup.h"

#include <atomic>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

std::atomic<int> g_validation_messages{0};

VKAPI_ATTR VkBool32 VKAPI_CALL CountValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                      VkDebugUtilsMessageTypeFlagsEXT,
                                                      const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
  ++g_validation_messages;
  std::fprintf(stderr, "validation: %s\n", data->pMessage);
  return VK_FALSE;
}

// Chained to the instance's creation too, so that its creation and destruction are reported.
VkDebugUtilsMessengerCreateInfoEXT MessengerInfo() {
  return {.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
          .messageSeverity =
              VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
          .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT,
          .pfnUserCallback = &CountValidationMessage};
}

template <typename Function>
Function InstanceFunction(VkInstance instance, const char* name) {
  auto function = reinterpret_cast<Function>(vkGetInstanceProcAddr(instance, name));
  if (function == nullptr) throw std::runtime_error(std::string("Vulkan function not found: ") + name);
  return function;
}

// A queue family that draws, computes and writes timestamps: what aerial needs of the queue.
bool FindQueueFamily(VkPhysicalDevice device, uint32_t& family) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  const VkQueueFlags wanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  for (uint32_t i = 0; i < count; ++i) {
    if ((families[i].queueFlags & wanted) == wanted && families[i].timestampValidBits > 0) {
      family = i;
      return true;
    }
  }
  return false;
}

}  // namespace

void Check(VkResult result, const char* call) {
  if (result != VK_SUCCESS) throw std::runtime_error(std::string(call) + " failed: VkResult " + std::to_string(result));
}

int ValidationMessageCount() { return g_validation_messages.load(); }

VulkanSetup::VulkanSetup(bool validation) {
  try {
    VkApplicationInfo application{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                                  .pApplicationName = "aerial embed example",
                                  .apiVersion = VK_API_VERSION_1_3};
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* debug_utils = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkDebugUtilsMessengerCreateInfoEXT messenger_info = MessengerInfo();
    VkInstanceCreateInfo instance_info{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                                       .pNext = validation ? &messenger_info : nullptr,
                                       .pApplicationInfo = &application,
                                       .enabledLayerCount = validation ? 1u : 0u,
                                       .ppEnabledLayerNames = &layer,
                                       .enabledExtensionCount = validation ? 1u : 0u,
                                       .ppEnabledExtensionNames = &debug_utils};
    Check(vkCreateInstance(&instance_info, nullptr, &instance), "vkCreateInstance");
    if (validation) {
      auto create = InstanceFunction<PFN_vkCreateDebugUtilsMessengerEXT>(instance, "vkCreateDebugUtilsMessengerEXT");
      Check(create(instance, &messenger_info, nullptr, &messenger), "vkCreateDebugUtilsMessengerEXT");
    }

    // The first Vulkan 1.3 device with a suitable queue family.
    uint32_t count = 0;
    Check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(count);
    Check(vkEnumeratePhysicalDevices(instance, &count, devices.data()), "vkEnumeratePhysicalDevices");
    for (VkPhysicalDevice candidate : devices) {
      VkPhysicalDeviceProperties properties;
      vkGetPhysicalDeviceProperties(candidate, &properties);
      if (properties.apiVersion >= VK_API_VERSION_1_3 && FindQueueFamily(candidate, queue_family)) {
        physical_device = candidate;
        break;
      }
    }
    if (physical_device == VK_NULL_HANDLE) throw std::runtime_error("no Vulkan 1.3 device that draws and computes");
    vkGetPhysicalDeviceMemoryProperties(physical_device, &memory);

    // aerial's features and extensions; an engine chains its own features after them.
    aerial::RequiredDeviceFeatures features;
    float priority = 1.0f;
    VkDeviceQueueCreateInfo queue_info{.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                       .queueFamilyIndex = queue_family,
                                       .queueCount = 1,
                                       .pQueuePriorities = &priority};
    VkDeviceCreateInfo device_info{.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                                   .pNext = features.Chain(),
                                   .queueCreateInfoCount = 1,
                                   .pQueueCreateInfos = &queue_info,
                                   .enabledExtensionCount = uint32_t(aerial::kRequiredDeviceExtensions.size()),
                                   .ppEnabledExtensionNames = aerial::kRequiredDeviceExtensions.data(),
                                   .pEnabledFeatures = &features.core};
    Check(vkCreateDevice(physical_device, &device_info, nullptr, &device), "vkCreateDevice");
    vkGetDeviceQueue(device, queue_family, 0, &queue);

    VkCommandPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                      .queueFamilyIndex = queue_family};
    Check(vkCreateCommandPool(device, &pool_info, nullptr, &command_pool), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo buffer_info{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                            .commandPool = command_pool,
                                            .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                            .commandBufferCount = 1};
    Check(vkAllocateCommandBuffers(device, &buffer_info, &command_buffer), "vkAllocateCommandBuffers");
    VkFenceCreateInfo fence_info{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    Check(vkCreateFence(device, &fence_info, nullptr, &frame_done), "vkCreateFence");
  } catch (...) {
    Destroy();  // a constructor that throws runs no destructor
    throw;
  }
}

VulkanSetup::~VulkanSetup() { Destroy(); }

void VulkanSetup::Destroy() {
  if (device != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device);
    vkDestroyFence(device, frame_done, nullptr);
    vkDestroyCommandPool(device, command_pool, nullptr);  // frees the command buffer too
    vkDestroyDevice(device, nullptr);
    device = VK_NULL_HANDLE;
  }
  if (instance != VK_NULL_HANDLE) {
    if (messenger != VK_NULL_HANDLE) {
      InstanceFunction<PFN_vkDestroyDebugUtilsMessengerEXT>(instance, "vkDestroyDebugUtilsMessengerEXT")(
          instance, messenger, nullptr);
    }
    vkDestroyInstance(instance, nullptr);
    instance = VK_NULL_HANDLE;
  }
}

aerial::DeviceHandoff VulkanSetup::Handoff() const {
  return {.instance = instance, .physical_device = physical_device, .device = device, .queue_family = queue_family,
          .queue_index = 0};
}

void VulkanSetup::SubmitFrameAndWait() const {
  VkSubmitInfo submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1,
                      .pCommandBuffers = &command_buffer};
  Check(vkResetFences(device, 1, &frame_done), "vkResetFences");
  Check(vkQueueSubmit(queue, 1, &submit, frame_done), "vkQueueSubmit");
  Check(vkWaitForFences(device, 1, &frame_done, VK_TRUE, UINT64_MAX), "vkWaitForFences");
}
