#include "backends/vulkan/VulkanMemory.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "backends/vulkan/VulkanResult.h"

namespace shaderbed::vulkan {

Result<uint32_t> find_memory_type(const VkPhysicalDeviceMemoryProperties& memory, uint32_t type_bits,
                                  VkMemoryPropertyFlags required) {
  for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
    if ((type_bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & required) == required) return i;
  return std::unexpected(backend_error("no memory type with property flags " + std::to_string(required) +
                                       " for type bits " + std::to_string(type_bits)));
}

Result<HostBuffer> HostBuffer::create(const VulkanDevice& device, VkDeviceSize size, VkBufferUsageFlags usage) {
  return create(device.device(), device.memory_properties(), size, usage);
}

Result<HostBuffer> HostBuffer::create(VkDevice dev, const VkPhysicalDeviceMemoryProperties& memory_types,
                                      VkDeviceSize size, VkBufferUsageFlags usage) {
  HostBuffer out;
  // Zero-sized buffers are invalid in Vulkan; an empty uniform block still gets a binding.
  out.size_ = std::max<VkDeviceSize>(size, 16);

  const VkBufferCreateInfo info{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                                .size = out.size_,
                                .usage = usage,
                                .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
  VkBuffer buffer;
  if (auto ok = check(vkCreateBuffer(dev, &info, nullptr, &buffer), "vkCreateBuffer"); !ok) return std::unexpected(ok.error());
  out.buffer_ = OwnedBuffer(dev, buffer);

  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(dev, buffer, &req);
  auto type = find_memory_type(memory_types, req.memoryTypeBits,
                               VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  if (!type) return std::unexpected(type.error());
  const VkMemoryAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                                   .allocationSize = req.size,
                                   .memoryTypeIndex = *type};
  VkDeviceMemory memory;
  if (auto ok = check(vkAllocateMemory(dev, &alloc, nullptr, &memory), "vkAllocateMemory"); !ok) return std::unexpected(ok.error());
  out.memory_ = OwnedMemory(dev, memory);
  if (auto ok = check(vkBindBufferMemory(dev, buffer, memory, 0), "vkBindBufferMemory"); !ok) return std::unexpected(ok.error());

  void* mapped = nullptr;
  if (auto ok = check(vkMapMemory(dev, memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory"); !ok) return std::unexpected(ok.error());
  out.mapped_ = static_cast<std::byte*>(mapped);
  std::memset(out.mapped_, 0, out.size_);
  return out;
}

void HostBuffer::write(std::span<const std::byte> bytes, VkDeviceSize offset) const {
  if (bytes.empty() || offset >= size_) return;
  std::memcpy(mapped_ + offset, bytes.data(), std::min<VkDeviceSize>(bytes.size(), size_ - offset));
}

Result<OwnedMemory> bind_device_memory(const VulkanDevice& device, VkImage image) {
  VkDevice dev = device.device();
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(dev, image, &req);
  auto type = find_memory_type(device.memory_properties(), req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (!type) return std::unexpected(type.error());
  const VkMemoryAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                                   .allocationSize = req.size,
                                   .memoryTypeIndex = *type};
  VkDeviceMemory memory;
  if (auto ok = check(vkAllocateMemory(dev, &alloc, nullptr, &memory), "vkAllocateMemory"); !ok) return std::unexpected(ok.error());
  OwnedMemory owned(dev, memory);
  if (auto ok = check(vkBindImageMemory(dev, image, memory, 0), "vkBindImageMemory"); !ok) return std::unexpected(ok.error());
  return owned;
}

Result<DeviceImage> DeviceImage::create(const VulkanDevice& device, VkFormat format, VkExtent2D extent,
                                        VkImageUsageFlags usage, VkImageAspectFlags aspect) {
  VkDevice dev = device.device();
  DeviceImage out;
  const VkImageCreateInfo info{.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
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
  VkImage image;
  if (auto ok = check(vkCreateImage(dev, &info, nullptr, &image), "vkCreateImage"); !ok) return std::unexpected(ok.error());
  out.image_ = OwnedImage(dev, image);

  auto memory = bind_device_memory(device, image);
  if (!memory) return std::unexpected(memory.error());
  out.memory_ = std::move(*memory);

  const VkImageViewCreateInfo view_info{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                        .image = image,
                                        .viewType = VK_IMAGE_VIEW_TYPE_2D,
                                        .format = format,
                                        .subresourceRange = {aspect, 0, 1, 0, 1}};
  VkImageView view;
  if (auto ok = check(vkCreateImageView(dev, &view_info, nullptr, &view), "vkCreateImageView"); !ok) return std::unexpected(ok.error());
  out.view_ = OwnedImageView(dev, view);
  return out;
}

}  // namespace shaderbed::vulkan
