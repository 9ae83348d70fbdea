#pragma once
// The engine's own buffers and images on its device, one allocation each (an engine would
// sub-allocate, e.g. with the Vulkan Memory Allocator).
#include <vulkan/vulkan_core.h>

#include "vulkan_setup.h"

// A buffer in host-visible, coherent memory, mapped for its lifetime: vertices and indices
// written once, and the frame's read-back. (A discrete GPU would rather draw from device-local
// memory through a staging copy; lavapipe has one kind of memory.)
struct MappedBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* data = nullptr;
};

MappedBuffer CreateMappedBuffer(const VulkanSetup& vulkan, VkDeviceSize size, VkBufferUsageFlags usage);
void Destroy(VkDevice device, MappedBuffer& buffer);

// A 2D image in device memory with a view of all of it.
struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
};

Image CreateImage(const VulkanSetup& vulkan, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                  VkImageAspectFlags aspect);
void Destroy(VkDevice device, Image& image);
