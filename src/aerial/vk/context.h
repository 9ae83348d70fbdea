#pragma once
// The Vulkan instance, the chosen device and its one compute+graphics queue. Raw Vulkan stays in
// src/aerial/vk/; the rest of the program works with Context, Buffer, Image and ComputePipeline.
#include <array>
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan_raii.hpp>

#include "aerial/device.h"
#include "aerial/vk/table_filtering.h"

namespace aerial::vk {

class PipelineCache;

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

class Context {
 public:
  explicit Context(const ContextCreateInfo& info = {});
  // Works on the caller's device (aerial/device.h says what it must have and what aerial does on
  // it); validation is then the caller's instance's.
  explicit Context(const DeviceHandoff& handoff);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const ::vk::raii::Instance& instance() const { return instance_; }
  const ::vk::raii::PhysicalDevice& physical_device() const { return physical_device_; }
  const ::vk::raii::Device& device() const { return device_; }
  const ::vk::raii::Queue& queue() const { return queue_; }
  uint32_t queue_family() const { return queue_family_; }
  std::string device_name() const;
  // Whether the device is a CPU (lavapipe): it runs shaders on the host's cores, rasterizes in bins
  // and renders into host memory.
  bool cpu_device() const;
  // This context's handles, to hand to aerial::Device (the viewer's window device, a bench's).
  DeviceHandoff Handoff() const;
  bool validation_enabled() const { return validation_; }
  // How this context's pipelines read the tables: AERIAL_TABLE_FILTERING (table_filtering.h).
  TableFiltering table_filtering() const { return table_filtering_; }
  double timestamp_period_ns() const { return timestamp_period_ns_; }
  // Whether pipeline-statistics queries may be used (the optional feature pipelineStatisticsQuery).
  bool pipeline_statistics() const { return pipeline_statistics_; }

  // Records commands, submits them and waits for completion: for one-off work (uploads,
  // readbacks, a single frame). The command buffer and fence are the context's own, reused by
  // every call, so a Submit must not be made from inside another one's record, nor from two
  // threads at once. Frames that should not wait use a CommandRing (command_ring.h).
  void Submit(const std::function<void(const CommandBuffer&)>& record) const;

  // The pipelines built on this context, shared by the passes that ask for the same one
  // (pipeline_cache.h).
  PipelineCache& pipelines() const { return *pipelines_; }

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
  TableFiltering table_filtering_ = TableFilteringFromEnvironment();
  bool external_ = false;  // the instance and the device are the caller's (DeviceHandoff)
  double timestamp_period_ns_ = 1.0;
  bool pipeline_statistics_ = false;
  // Last: its pipelines go before the device does.
  std::unique_ptr<PipelineCache> pipelines_;
};

// A caller's command buffer (the public API's VkCommandBuffer) as aerial's passes record into
// it, for the length of one call; it stays the caller's, who allocated it and frees it.
class BorrowedCommandBuffer {
 public:
  BorrowedCommandBuffer(const Context& context, VkCommandBuffer handle)
      : buffer_(context.device(), handle, VK_NULL_HANDLE) {}
  ~BorrowedCommandBuffer() { buffer_.release(); }
  BorrowedCommandBuffer(const BorrowedCommandBuffer&) = delete;
  BorrowedCommandBuffer& operator=(const BorrowedCommandBuffer&) = delete;
  const CommandBuffer& operator*() const { return buffer_; }

 private:
  CommandBuffer buffer_;
};

}  // namespace aerial::vk
