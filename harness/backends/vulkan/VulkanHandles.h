#pragma once
// Move-only owners for device-level Vulkan handles, so every early error return in
// render() releases exactly what was created so far, in reverse order of creation.
#include <utility>

#include <vulkan/vulkan.h>

namespace shaderbed::vulkan {

template <class Handle, void (*Destroy)(VkDevice, Handle, const VkAllocationCallbacks*)>
class DeviceObject {
 public:
  DeviceObject() = default;
  DeviceObject(VkDevice device, Handle handle) : device_(device), handle_(handle) {}
  ~DeviceObject() { reset(); }

  DeviceObject(const DeviceObject&) = delete;
  DeviceObject& operator=(const DeviceObject&) = delete;
  DeviceObject(DeviceObject&& other) noexcept
      : device_(other.device_), handle_(std::exchange(other.handle_, VK_NULL_HANDLE)) {}
  DeviceObject& operator=(DeviceObject&& other) noexcept {
    if (this != &other) {
      reset();
      device_ = other.device_;
      handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
    }
    return *this;
  }

  Handle get() const { return handle_; }
  explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

  void reset() {
    if (handle_ != VK_NULL_HANDLE) Destroy(device_, handle_, nullptr);
    handle_ = VK_NULL_HANDLE;
  }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  Handle handle_ = VK_NULL_HANDLE;
};

using OwnedBuffer = DeviceObject<VkBuffer, vkDestroyBuffer>;
using OwnedImage = DeviceObject<VkImage, vkDestroyImage>;
using OwnedImageView = DeviceObject<VkImageView, vkDestroyImageView>;
using OwnedSampler = DeviceObject<VkSampler, vkDestroySampler>;
using OwnedMemory = DeviceObject<VkDeviceMemory, vkFreeMemory>;
using OwnedRenderPass = DeviceObject<VkRenderPass, vkDestroyRenderPass>;
using OwnedFramebuffer = DeviceObject<VkFramebuffer, vkDestroyFramebuffer>;
using OwnedShaderModule = DeviceObject<VkShaderModule, vkDestroyShaderModule>;
using OwnedDescriptorSetLayout = DeviceObject<VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;
using OwnedDescriptorPool = DeviceObject<VkDescriptorPool, vkDestroyDescriptorPool>;
using OwnedPipelineLayout = DeviceObject<VkPipelineLayout, vkDestroyPipelineLayout>;
using OwnedPipeline = DeviceObject<VkPipeline, vkDestroyPipeline>;
using OwnedCommandPool = DeviceObject<VkCommandPool, vkDestroyCommandPool>;
using OwnedFence = DeviceObject<VkFence, vkDestroyFence>;
using OwnedQueryPool = DeviceObject<VkQueryPool, vkDestroyQueryPool>;

}  // namespace shaderbed::vulkan
