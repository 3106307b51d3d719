#pragma once
// The offscreen target every draw renders into: float RGBA colour (so values outside
// [0,1], Inf and NaN survive) plus a 32-bit float depth buffer whose written pixels are
// the coverage mask, and host buffers the two images are copied into for readback.
#include <memory>

#include <vulkan/vulkan.h>

#include "backends/vulkan/VulkanDevice.h"
#include "backends/vulkan/VulkanHandles.h"
#include "backends/vulkan/VulkanMemory.h"
#include "core/Error.h"
#include "core/Image.h"

namespace shaderbed::vulkan {

inline constexpr VkFormat colour_format = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat depth_format = VK_FORMAT_D32_SFLOAT;
inline constexpr VkClearColorValue colour_clear{.float32 = {0.0f, 0.0f, 0.0f, 0.0f}};
inline constexpr float depth_clear = 1.0f;

// Error unless the device can render to and copy from both target formats.
Result<void> check_target_formats(const VulkanDevice& device);

// One render pass for every target (its compatibility only depends on the formats):
// clears both attachments, keeps them, and leaves them ready to be copied from.
Result<OwnedRenderPass> create_render_pass(const VulkanDevice& device);

class RenderTarget {
 public:
  static Result<std::unique_ptr<RenderTarget>> create(const VulkanDevice& device, VkRenderPass render_pass,
                                                      VkExtent2D extent);

  VkExtent2D extent() const { return extent_; }
  VkFramebuffer framebuffer() const { return framebuffer_.get(); }

  // Copies colour and depth (in TRANSFER_SRC layout after the render pass) into the
  // readback buffers and makes them visible to the host.
  void record_readback(VkCommandBuffer commands) const;
  // After record_readback's submission completed: the pixels, row 0 at the top.
  Image read_image() const;

 private:
  VkExtent2D extent_{};
  DeviceImage colour_;
  DeviceImage depth_;
  OwnedFramebuffer framebuffer_;
  HostBuffer colour_readback_;
  HostBuffer depth_readback_;
};

}  // namespace shaderbed::vulkan
