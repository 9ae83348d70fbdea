// The engine's buffers and images (gpu_memory.h).
#include "gpu_memory.h"

#include <stdexcept>

namespace {

// A memory type allowed by `allowed` (a resource's memoryTypeBits) with all of `wanted`.
uint32_t FindMemoryType(const VkPhysicalDeviceMemoryProperties& memory, uint32_t allowed,
                        VkMemoryPropertyFlags wanted) {
  for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
    if ((allowed & (1u << i)) && (memory.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
  throw std::runtime_error("no suitable Vulkan memory type");
}

VkDeviceMemory Allocate(const VulkanSetup& vulkan, const VkMemoryRequirements& requirements,
                        VkMemoryPropertyFlags wanted) {
  VkMemoryAllocateInfo info{.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                            .allocationSize = requirements.size,
                            .memoryTypeIndex = FindMemoryType(vulkan.memory, requirements.memoryTypeBits, wanted)};
  VkDeviceMemory memory = VK_NULL_HANDLE;
  Check(vkAllocateMemory(vulkan.device, &info, nullptr, &memory), "vkAllocateMemory");
  return memory;
}

}  // namespace

MappedBuffer CreateMappedBuffer(const VulkanSetup& vulkan, VkDeviceSize size, VkBufferUsageFlags usage) {
  MappedBuffer result;
  VkBufferCreateInfo info{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO, .size = size, .usage = usage,
                          .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
  Check(vkCreateBuffer(vulkan.device, &info, nullptr, &result.buffer), "vkCreateBuffer");
  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(vulkan.device, result.buffer, &requirements);
  result.memory =
      Allocate(vulkan, requirements, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  Check(vkBindBufferMemory(vulkan.device, result.buffer, result.memory, 0), "vkBindBufferMemory");
  Check(vkMapMemory(vulkan.device, result.memory, 0, VK_WHOLE_SIZE, 0, &result.data), "vkMapMemory");
  return result;
}

void Destroy(VkDevice device, MappedBuffer& buffer) {
  vkDestroyBuffer(device, buffer.buffer, nullptr);
  vkFreeMemory(device, buffer.memory, nullptr);  // unmaps it
  buffer = {};
}

Image CreateImage(const VulkanSetup& vulkan, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                  VkImageAspectFlags aspect) {
  Image result;
  VkImageCreateInfo info{.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                         .imageType = VK_IMAGE_TYPE_2D,
                         .format = format,
                         .extent = {extent.width, extent.height, 1},
                         .mipLevels = 1,
                         .arrayLayers = 1,
                         .samples = VK_SAMPLE_COUNT_1_BIT,
                         .tiling = VK_IMAGE_TILING_OPTIMAL,
                         .usage = usage,
                         .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
                         .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
  Check(vkCreateImage(vulkan.device, &info, nullptr, &result.image), "vkCreateImage");
  VkMemoryRequirements requirements;
  vkGetImageMemoryRequirements(vulkan.device, result.image, &requirements);
  result.memory = Allocate(vulkan, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  Check(vkBindImageMemory(vulkan.device, result.image, result.memory, 0), "vkBindImageMemory");
  VkImageViewCreateInfo view{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                             .image = result.image,
                             .viewType = VK_IMAGE_VIEW_TYPE_2D,
                             .format = format,
                             .subresourceRange = {.aspectMask = aspect, .levelCount = 1, .layerCount = 1}};
  Check(vkCreateImageView(vulkan.device, &view, nullptr, &result.view), "vkCreateImageView");
  return result;
}

void Destroy(VkDevice device, Image& image) {
  vkDestroyImageView(device, image.view, nullptr);
  vkDestroyImage(device, image.image, nullptr);
  vkFreeMemory(device, image.memory, nullptr);
  image = {};
}
