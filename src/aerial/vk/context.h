#pragma once
// The Vulkan instance, the chosen device and its one compute+graphics queue. Raw Vulkan stays in
// src/aerial/vk/; the rest of the program works with Context, Buffer, Image and ComputePipeline.
#include <array>
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan_raii.hpp>

namespace aerial::vk {

// The command buffer that passes record into: the caller's own per frame, the context's for
// one-off work (Context::Submit).
using CommandBuffer = ::vk::raii::CommandBuffer;

struct ContextCreateInfo {
  // Substring of the device name to pick (case-insensitive); empty: AERIAL_DEVICE or the best.
  std::string device_name;
  // Validation layers: on when true or when AERIAL_VALIDATION=1 is set.
  bool validation = false;
  // Instance extensions a window system needs (GLFW); the swapchain device extension is then
  // requested too.
  std::vector<std::string> window_extensions;
  // When set, the queue must also be able to present to the window system (for GLFW,
  // glfwGetPhysicalDevicePresentationSupport); asked once the instance exists.
  std::function<bool(::vk::Instance, ::vk::PhysicalDevice, uint32_t queue_family)> present_support;
};

// A Vulkan device that the caller created and keeps, for aerial to work on: a client's own
// renderer (docs in README, "Using aerial as a library"). The instance and the device must be
// made for Vulkan 1.3 with what aerial needs: the extensions of kRequiredDeviceExtensions and the
// features of RequiredDeviceFeatures. aerial checks the version, the queue family and that the
// extensions are supported; which features were enabled it cannot see. On that device aerial
// makes its own command pool, fence and resources, submits one-off work (uploads, the
// precompute, read-backs) to the queue, which the caller must not use from another thread
// meanwhile, and destroys neither the device nor the instance. Frames are recorded into the
// caller's command buffers (Renderer::Record, FroxelVolume::Build), which the caller submits.
struct ExternalDevice {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queue_family = 0;  // graphics and compute, with timestamps
  uint32_t queue_index = 0;
};

// The device extensions aerial uses (descriptors are pushed, not allocated from pools).
inline constexpr std::array<const char*, 1> kRequiredDeviceExtensions = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};

// The device features aerial uses: storage images written without a format in the shader
// (precompute), dynamic rendering (the frame's raster passes) and host query reset (timers).
struct RequiredDeviceFeatures {
  ::vk::PhysicalDeviceFeatures core{.shaderStorageImageWriteWithoutFormat = VK_TRUE};
  ::vk::PhysicalDeviceVulkan12Features vulkan12{.hostQueryReset = VK_TRUE};
  ::vk::PhysicalDeviceVulkan13Features vulkan13{.dynamicRendering = VK_TRUE};
  // The chain for VkDeviceCreateInfo::pNext, with pEnabledFeatures = &core; next: the caller's
  // own chain, placed after it. Valid while this object lives and stays where it is.
  void* Chain(void* next = nullptr) {
    vulkan13.pNext = next;
    vulkan12.pNext = &vulkan13;
    return &vulkan12;
  }
};

class Context {
 public:
  explicit Context(const ContextCreateInfo& info = {});
  // Works on the caller's device (ExternalDevice); validation is then the caller's instance's.
  explicit Context(const ExternalDevice& external);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const ::vk::raii::Instance& instance() const { return instance_; }
  const ::vk::raii::PhysicalDevice& physical_device() const { return physical_device_; }
  const ::vk::raii::Device& device() const { return device_; }
  const ::vk::raii::Queue& queue() const { return queue_; }
  uint32_t queue_family() const { return queue_family_; }
  std::string device_name() const;
  bool validation_enabled() const { return validation_; }
  double timestamp_period_ns() const { return timestamp_period_ns_; }

  // Records commands, submits them and waits for completion: for one-off work (uploads,
  // readbacks, a single frame). The command buffer and fence are the context's own, reused by
  // every call, so a Submit must not be made from inside another one's record, nor from two
  // threads at once. Frames that should not wait use a CommandRing (command_ring.h).
  void Submit(const std::function<void(const CommandBuffer&)>& record) const;

  // The size of the device's largest device-local memory heap, in bytes.
  uint64_t largest_heap_bytes() const;

  uint32_t FindMemoryType(uint32_t type_bits, ::vk::MemoryPropertyFlags properties) const;

  // Number of validation messages (warnings and errors) seen by any context of this process.
  static int ValidationMessageCount();

 private:
  void CheckQueueFamily(const std::function<bool(uint32_t)>& can_present) const;
  void CreateSubmitObjects();
  void ReleaseCallersHandles();

  ::vk::raii::Context loader_;
  ::vk::raii::Instance instance_{nullptr};
  std::optional<::vk::raii::DebugUtilsMessengerEXT> messenger_;
  ::vk::raii::PhysicalDevice physical_device_{nullptr};
  ::vk::raii::Device device_{nullptr};
  ::vk::raii::Queue queue_{nullptr};
  ::vk::raii::CommandPool command_pool_{nullptr};
  ::vk::raii::CommandBuffer submit_buffer_{nullptr};
  ::vk::raii::Fence submit_done_{nullptr};
  uint32_t queue_family_ = 0;
  bool validation_ = false;
  bool external_ = false;  // the instance and the device are the caller's (ExternalDevice)
  double timestamp_period_ns_ = 1.0;
};

}  // namespace aerial::vk
