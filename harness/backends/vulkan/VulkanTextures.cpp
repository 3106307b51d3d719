#include "backends/vulkan/VulkanTextures.h"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "backends/TextureShape.h"
#include "backends/vulkan/VulkanResult.h"

namespace shaderbed::vulkan {
namespace {

std::string where(const SamplerBinding& sampler) {
  return "sampler '" + sampler.name + "' (set " + std::to_string(sampler.set) + ", binding " +
         std::to_string(sampler.binding) + ")";
}

// The texture fits the sampler: same dimensionality, unused extents 1, texel count
// w*h*d, and within the device's image limits.
Result<void> check_texture(const VulkanDevice& device, const SamplerBinding& sampler, const Texture& t) {
  const std::string what = where(sampler) + ": texture '" + t.name + "'";
  const VkPhysicalDeviceLimits& limits = device.properties().limits;
  const uint32_t max_extent = t.dimensions == 1   ? limits.maxImageDimension1D
                              : t.dimensions == 2 ? limits.maxImageDimension2D
                                                  : limits.maxImageDimension3D;
  if (std::string problem = texture_mismatch(what, sampler, t, max_extent, "the device's image"); !problem.empty())
    return std::unexpected(backend_error(problem));
  return {};
}

Result<void> check_format_support(const VulkanDevice& device) {
  constexpr VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                          VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT |
                                          VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
  VkFormatProperties props;
  vkGetPhysicalDeviceFormatProperties(device.physical_device(), texture_format, &props);
  if ((props.optimalTilingFeatures & needed) == needed) return {};
  std::string missing;
  const auto note = [&](VkFormatFeatureFlags bit, const char* name) {
    if (!(props.optimalTilingFeatures & bit)) missing += std::string(missing.empty() ? "" : ", ") + name;
  };
  note(VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT, "sampling");
  note(VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT, "linear filtering");
  note(VK_FORMAT_FEATURE_TRANSFER_DST_BIT, "transfer destination");
  return std::unexpected(backend_error(std::string(device.properties().deviceName) +
                                       " cannot use R32_SFLOAT optimal-tiling images for lookup textures (no " +
                                       missing + ")"));
}

Result<OwnedSampler> create_sampler(VkDevice device) {
  // The book's LUT sampling (D3DTEXF_LINEAR, D3DTADDRESS_CLAMP, one level): bilinear or
  // trilinear within level 0, never a mip blend, texel centres at (i + 0.5) / size.
  const VkSamplerCreateInfo info{.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
                                 .magFilter = VK_FILTER_LINEAR,
                                 .minFilter = VK_FILTER_LINEAR,
                                 .mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                 .addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                 .addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                 .addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                 .mipLodBias = 0.0f,
                                 .anisotropyEnable = VK_FALSE,
                                 .maxAnisotropy = 1.0f,
                                 .compareEnable = VK_FALSE,
                                 .compareOp = VK_COMPARE_OP_ALWAYS,
                                 .minLod = 0.0f,
                                 .maxLod = 0.0f,
                                 .borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK,
                                 .unnormalizedCoordinates = VK_FALSE};
  VkSampler sampler;
  if (auto ok = check(vkCreateSampler(device, &info, nullptr, &sampler), "vkCreateSampler"); !ok)
    return std::unexpected(ok.error());
  return OwnedSampler(device, sampler);
}

VkImageType image_type(uint32_t dimensions) {
  return dimensions == 1 ? VK_IMAGE_TYPE_1D : dimensions == 2 ? VK_IMAGE_TYPE_2D : VK_IMAGE_TYPE_3D;
}

VkImageViewType view_type(uint32_t dimensions) {
  return dimensions == 1 ? VK_IMAGE_VIEW_TYPE_1D : dimensions == 2 ? VK_IMAGE_VIEW_TYPE_2D : VK_IMAGE_VIEW_TYPE_3D;
}

}  // namespace

Result<std::vector<SamplerBinding>> program_samplers(const CompiledProgram& program,
                                                     const std::vector<UniformBlock>& blocks) {
  std::map<std::pair<uint32_t, uint32_t>, SamplerBinding> by_binding;
  for (const ShaderModule* module : {&program.vertex, &program.fragment}) {
    for (const SamplerBinding& sampler : module->reflection.samplers) {
      const auto block = std::ranges::find_if(blocks, [&](const UniformBlock& b) {
        return b.set == sampler.set && b.binding == sampler.binding;
      });
      if (block != blocks.end())
        return std::unexpected(backend_error(where(sampler) + " and uniform block '" + block->name +
                                             "' share one descriptor binding")
                                   .in_file(module->source_file));
      auto [it, inserted] = by_binding.try_emplace({sampler.set, sampler.binding}, sampler);
      if (!inserted && (it->second.name != sampler.name || it->second.dimensions != sampler.dimensions))
        return std::unexpected(backend_error("the vertex and fragment shaders declare different samplers at set " +
                                             std::to_string(sampler.set) + ", binding " +
                                             std::to_string(sampler.binding) + " ('" + it->second.name + "' " +
                                             dimensions_text(it->second.dimensions) + " and '" + sampler.name + "' " +
                                             dimensions_text(sampler.dimensions) + ")"));
    }
  }
  std::vector<SamplerBinding> samplers;
  for (auto& [key, sampler] : by_binding) samplers.push_back(std::move(sampler));
  return samplers;
}

Result<std::vector<ResolvedTexture>> resolve_textures(const VulkanDevice& device,
                                                      const std::vector<SamplerBinding>& samplers,
                                                      const TextureResolver* resolver) {
  std::vector<ResolvedTexture> resolved;
  if (samplers.empty()) return resolved;
  if (resolver == nullptr)
    return std::unexpected(backend_error("the program declares " + where(samplers.front()) +
                                         " but the draw has no textures (DrawJob::textures is null)"));
  for (const SamplerBinding& sampler : samplers) {
    auto texture = resolver->texture(sampler);
    if (!texture) {
      Error e = std::move(texture.error());
      if (e.message.find("'" + sampler.name + "'") == std::string::npos) e.message = where(sampler) + ": " + e.message;
      return std::unexpected(std::move(e).in_stage("vulkan"));
    }
    if (*texture == nullptr)
      return std::unexpected(backend_error(where(sampler) + ": the texture resolver returned no texture"));
    if (auto ok = check_texture(device, sampler, **texture); !ok) return std::unexpected(ok.error());
    resolved.push_back({sampler, *texture});
  }
  return resolved;
}

Result<DrawTextures> DrawTextures::create(const VulkanDevice& device, const std::vector<ResolvedTexture>& textures) {
  DrawTextures out;
  if (textures.empty()) return out;
  if (auto ok = check_format_support(device); !ok) return std::unexpected(ok.error());
  const VkPhysicalDeviceLimits& limits = device.properties().limits;
  // Every sampler is visible to both stages, so each counts against both stages' limits.
  const uint32_t stage_limit = std::min(limits.maxPerStageDescriptorSamplers, limits.maxPerStageDescriptorSampledImages);
  if (textures.size() > stage_limit)
    return std::unexpected(backend_error("the program declares " + std::to_string(textures.size()) +
                                         " samplers; the device allows " + std::to_string(stage_limit) + " per stage"));

  VkDevice dev = device.device();
  auto sampler = create_sampler(dev);
  if (!sampler) return std::unexpected(sampler.error());
  out.sampler_ = std::move(*sampler);

  std::map<const Texture*, size_t> uploaded;  // one image per distinct texture
  for (const ResolvedTexture& r : textures) {
    auto [slot, is_new] = uploaded.try_emplace(r.texture, out.images_.size());
    if (is_new) {
      const Texture& t = *r.texture;
      const std::span<const std::byte> bytes = std::as_bytes(std::span(t.texels));
      auto staging = HostBuffer::create(device, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
      if (!staging) return std::unexpected(staging.error());
      staging->write(bytes);

      Image image;
      image.extent = {t.width, t.height, t.depth};
      const VkImageCreateInfo info{.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                                   .imageType = image_type(t.dimensions),
                                   .format = texture_format,
                                   .extent = image.extent,
                                   .mipLevels = 1,
                                   .arrayLayers = 1,
                                   .samples = VK_SAMPLE_COUNT_1_BIT,
                                   .tiling = VK_IMAGE_TILING_OPTIMAL,
                                   .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                   .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
                                   .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
      VkImage handle;
      if (auto ok = check(vkCreateImage(dev, &info, nullptr, &handle), "vkCreateImage"); !ok)
        return std::unexpected(ok.error());
      image.image = OwnedImage(dev, handle);

      VkMemoryRequirements req;
      vkGetImageMemoryRequirements(dev, handle, &req);
      auto type = device.memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
      if (!type) return std::unexpected(type.error());
      const VkMemoryAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                                       .allocationSize = req.size,
                                       .memoryTypeIndex = *type};
      VkDeviceMemory memory;
      if (auto ok = check(vkAllocateMemory(dev, &alloc, nullptr, &memory), "vkAllocateMemory"); !ok)
        return std::unexpected(ok.error());
      image.memory = OwnedMemory(dev, memory);
      if (auto ok = check(vkBindImageMemory(dev, handle, memory, 0), "vkBindImageMemory"); !ok)
        return std::unexpected(ok.error());

      const VkImageViewCreateInfo view_info{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                            .image = handle,
                                            .viewType = view_type(t.dimensions),
                                            .format = texture_format,
                                            .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}};
      VkImageView view;
      if (auto ok = check(vkCreateImageView(dev, &view_info, nullptr, &view), "vkCreateImageView"); !ok)
        return std::unexpected(ok.error());
      image.view = OwnedImageView(dev, view);

      out.images_.push_back(std::move(image));
      out.staging_.push_back(std::move(*staging));
    }
    out.descriptors_.push_back({.set = r.sampler.set,
                                .binding = r.sampler.binding,
                                .view = out.images_[slot->second].view.get(),
                                .sampler = out.sampler_.get()});
  }
  return out;
}

void DrawTextures::record_uploads(VkCommandBuffer commands) const {
  constexpr VkImageSubresourceRange whole{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  std::vector<VkImageMemoryBarrier> to_transfer, to_shader;
  for (const Image& image : images_) {
    to_transfer.push_back({.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
                           .srcAccessMask = 0,
                           .dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                           .oldLayout = VK_IMAGE_LAYOUT_UNDEFINED,
                           .newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                           .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                           .image = image.image.get(),
                           .subresourceRange = whole});
    to_shader.push_back({.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
                         .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                         .dstAccessMask = VK_ACCESS_SHADER_READ_BIT,
                         .oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         .newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                         .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                         .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                         .image = image.image.get(),
                         .subresourceRange = whole});
  }
  vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                       nullptr, uint32_t(to_transfer.size()), to_transfer.data());
  for (size_t i = 0; i < images_.size(); ++i) {
    // Tightly packed, x fastest, then y, then z: Texture's order is the buffer's.
    const VkBufferImageCopy region{.bufferOffset = 0,
                                   .bufferRowLength = 0,
                                   .bufferImageHeight = 0,
                                   .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                   .imageOffset = {0, 0, 0},
                                   .imageExtent = images_[i].extent};
    vkCmdCopyBufferToImage(commands, staging_[i].buffer(), images_[i].image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           1, &region);
  }
  vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 0, nullptr, 0,
                       nullptr, uint32_t(to_shader.size()), to_shader.data());
}

}  // namespace shaderbed::vulkan
