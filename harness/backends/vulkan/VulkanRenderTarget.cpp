#include "backends/vulkan/VulkanRenderTarget.h"

#include <array>
#include <cstring>
#include <string>

#include "backends/vulkan/VulkanResult.h"

namespace shaderbed::vulkan {

Result<void> check_target_formats(const VulkanDevice& device) {
  struct Need {
    VkFormat format;
    VkFormatFeatureFlags features;
    const char* name;
  };
  const std::array needs{
      Need{colour_format, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT,
           "R32G32B32A32_SFLOAT colour attachment"},
      Need{depth_format, VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT,
           "D32_SFLOAT depth attachment"},
  };
  for (const Need& need : needs) {
    VkFormatProperties props;
    vkGetPhysicalDeviceFormatProperties(device.physical_device(), need.format, &props);
    if ((props.optimalTilingFeatures & need.features) != need.features)
      return std::unexpected(backend_error(std::string(device.properties().deviceName) + " does not support a " +
                                           need.name + " that can be copied from"));
  }
  return {};
}

Result<OwnedRenderPass> create_render_pass(const VulkanDevice& device) {
  const std::array attachments{
      VkAttachmentDescription{.format = colour_format,
                              .samples = VK_SAMPLE_COUNT_1_BIT,
                              .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                              .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                              .stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                              .stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
                              .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED,
                              .finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL},
      VkAttachmentDescription{.format = depth_format,
                              .samples = VK_SAMPLE_COUNT_1_BIT,
                              .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                              .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                              .stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                              .stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
                              .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED,
                              .finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL},
  };
  const VkAttachmentReference colour_ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  const VkAttachmentReference depth_ref{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  const VkSubpassDescription subpass{.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS,
                                     .colorAttachmentCount = 1,
                                     .pColorAttachments = &colour_ref,
                                     .pDepthStencilAttachment = &depth_ref};
  constexpr VkPipelineStageFlags attachment_stages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                     VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                     VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  constexpr VkAccessFlags attachment_writes =
      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  const std::array dependencies{
      // The target is reused: the previous draw's readback copy must finish reading
      // before this draw clears it (write-after-read needs only an execution dependency).
      VkSubpassDependency{.srcSubpass = VK_SUBPASS_EXTERNAL,
                          .dstSubpass = 0,
                          .srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT,
                          .dstStageMask = attachment_stages,
                          .srcAccessMask = 0,
                          .dstAccessMask = attachment_writes},
      // The readback copy reads what the draw wrote.
      VkSubpassDependency{.srcSubpass = 0,
                          .dstSubpass = VK_SUBPASS_EXTERNAL,
                          .srcStageMask = attachment_stages,
                          .dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT,
                          .srcAccessMask = attachment_writes,
                          .dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT},
  };
  const VkRenderPassCreateInfo info{.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO,
                                    .attachmentCount = uint32_t(attachments.size()),
                                    .pAttachments = attachments.data(),
                                    .subpassCount = 1,
                                    .pSubpasses = &subpass,
                                    .dependencyCount = uint32_t(dependencies.size()),
                                    .pDependencies = dependencies.data()};
  VkRenderPass pass;
  if (auto ok = check(vkCreateRenderPass(device.device(), &info, nullptr, &pass), "vkCreateRenderPass"); !ok)
    return std::unexpected(ok.error());
  return OwnedRenderPass(device.device(), pass);
}

Result<std::unique_ptr<RenderTarget>> RenderTarget::create(const VulkanDevice& device, VkRenderPass render_pass,
                                                           VkExtent2D extent) {
  auto target = std::make_unique<RenderTarget>();
  target->extent_ = extent;

  auto colour = DeviceImage::create(device, colour_format, extent,
                                    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                    VK_IMAGE_ASPECT_COLOR_BIT);
  if (!colour) return std::unexpected(colour.error());
  target->colour_ = std::move(*colour);
  auto depth = DeviceImage::create(device, depth_format, extent,
                                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                   VK_IMAGE_ASPECT_DEPTH_BIT);
  if (!depth) return std::unexpected(depth.error());
  target->depth_ = std::move(*depth);

  const std::array views{target->colour_.view(), target->depth_.view()};
  const VkFramebufferCreateInfo fb_info{.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO,
                                        .renderPass = render_pass,
                                        .attachmentCount = uint32_t(views.size()),
                                        .pAttachments = views.data(),
                                        .width = extent.width,
                                        .height = extent.height,
                                        .layers = 1};
  VkFramebuffer framebuffer;
  if (auto ok = check(vkCreateFramebuffer(device.device(), &fb_info, nullptr, &framebuffer), "vkCreateFramebuffer"); !ok)
    return std::unexpected(ok.error());
  target->framebuffer_ = OwnedFramebuffer(device.device(), framebuffer);

  const VkDeviceSize pixels = VkDeviceSize(extent.width) * extent.height;
  auto colour_readback = HostBuffer::create(device, pixels * 4 * sizeof(float), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  if (!colour_readback) return std::unexpected(colour_readback.error());
  target->colour_readback_ = std::move(*colour_readback);
  auto depth_readback = HostBuffer::create(device, pixels * sizeof(float), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  if (!depth_readback) return std::unexpected(depth_readback.error());
  target->depth_readback_ = std::move(*depth_readback);
  return target;
}

void RenderTarget::record_readback(VkCommandBuffer commands) const {
  // Tightly packed rows (bufferRowLength 0), image row 0 first: with the negative
  // viewport height row 0 is the top of the picture, as Image wants.
  const VkBufferImageCopy colour_region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                        .imageExtent = {extent_.width, extent_.height, 1}};
  vkCmdCopyImageToBuffer(commands, colour_.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, colour_readback_.buffer(), 1,
                         &colour_region);
  const VkBufferImageCopy depth_region{.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1},
                                       .imageExtent = {extent_.width, extent_.height, 1}};
  vkCmdCopyImageToBuffer(commands, depth_.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, depth_readback_.buffer(), 1,
                         &depth_region);

  const VkMemoryBarrier to_host{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                                .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                                .dstAccessMask = VK_ACCESS_HOST_READ_BIT};
  vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0, nullptr,
                       0, nullptr);
}

Image RenderTarget::read_image() const {
  Image image(int(extent_.width), int(extent_.height));
  // A byte copy: floats arrive exactly as the shader wrote them (no clamping, NaN
  // payloads and signs kept).
  std::memcpy(image.rgba.data(), colour_readback_.data(), image.rgba.size() * sizeof(float));
  const auto* depth = reinterpret_cast<const float*>(depth_readback_.data());
  for (size_t i = 0; i < image.coverage.size(); ++i) image.coverage[i] = depth[i] < depth_clear ? 1 : 0;
  return image;
}

}  // namespace shaderbed::vulkan
