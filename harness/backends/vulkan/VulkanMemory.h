#pragma once
// Buffers and images with their own memory. Every buffer is host-visible and coherent:
// on lavapipe all memory is host memory, so staging copies would only add time.
#include <cstddef>
#include <span>

#include <vulkan/vulkan.h>

#include "backends/vulkan/VulkanDevice.h"
#include "backends/vulkan/VulkanHandles.h"
#include "core/Error.h"

namespace shaderbed::vulkan {

// The first memory type in `type_bits` with all of `required`.
Result<uint32_t> find_memory_type(const VkPhysicalDeviceMemoryProperties& memory, uint32_t type_bits,
                                  VkMemoryPropertyFlags required);

class HostBuffer {
 public:
  static Result<HostBuffer> create(const VulkanDevice& device, VkDeviceSize size, VkBufferUsageFlags usage);
  // The same on a device that is not a VulkanDevice (the viewer's presentation device).
  static Result<HostBuffer> create(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory, VkDeviceSize size,
                                   VkBufferUsageFlags usage);

  VkBuffer buffer() const { return buffer_.get(); }
  VkDeviceSize size() const { return size_; }
  std::byte* data() const { return mapped_; }
  void write(std::span<const std::byte> bytes, VkDeviceSize offset = 0) const;

 private:
  // Members destroy in reverse order: the buffer goes before the memory bound to it.
  OwnedMemory memory_;
  OwnedBuffer buffer_;
  VkDeviceSize size_ = 0;
  std::byte* mapped_ = nullptr;  // mapped for the buffer's lifetime; unmapped by vkFreeMemory
};

// Device-local memory allocated for `image` and bound to it.
Result<OwnedMemory> bind_device_memory(const VulkanDevice& device, VkImage image);

class DeviceImage {
 public:
  static Result<DeviceImage> create(const VulkanDevice& device, VkFormat format, VkExtent2D extent,
                                    VkImageUsageFlags usage, VkImageAspectFlags aspect);

  VkImage image() const { return image_.get(); }
  VkImageView view() const { return view_.get(); }

 private:
  OwnedMemory memory_;
  OwnedImage image_;
  OwnedImageView view_;
};

}  // namespace shaderbed::vulkan
