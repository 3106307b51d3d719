#include "backends/vulkan/VulkanTextures.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "backends/TextureShape.h"
#include "backends/vulkan/VulkanResult.h"

namespace shaderbed::vulkan {
namespace {

const char* kind_text(SamplerKind kind) {
  return kind == SamplerKind::combined ? "sampler" : kind == SamplerKind::image ? "texture" : "sampler state";
}

std::string where(const SamplerBinding& sampler) {
  return std::string(kind_text(sampler.kind)) + " '" + sampler.name + "' (set " + std::to_string(sampler.set) +
         ", binding " + std::to_string(sampler.binding) + ")";
}

bool has_texture(const SamplerBinding& s) { return s.kind != SamplerKind::sampler; }
bool has_settings(const SamplerBinding& s) { return s.kind != SamplerKind::image; }

// The texture fits the sampler: same dimensionality, unused extents 1, texel count of
// every level, and within the device's image limits.
Result<void> check_texture(const VulkanDevice& device, const SamplerBinding& sampler, const Texture& t) {
  const std::string what = where(sampler) + ": texture '" + t.name + "'";
  const VkPhysicalDeviceLimits& limits = device.properties().limits;
  const uint32_t max_extent = t.cube              ? limits.maxImageDimensionCube
                              : t.dimensions == 1 ? limits.maxImageDimension1D
                              : t.dimensions == 2 ? limits.maxImageDimension2D
                                                  : limits.maxImageDimension3D;
  if (std::string problem = texture_mismatch(what, sampler, t, max_extent, "the device's image"); !problem.empty())
    return std::unexpected(backend_error(problem));
  return {};
}

// Vulkan 1.0 border colours are three fixed ones (VK_EXT_custom_border_color is not
// enabled on the device): any other colour is refused rather than silently changed.
Result<VkBorderColor> border_color(const SamplerSettings& s) {
  const auto is = [&](float r, float g, float b, float a) {
    return s.border_color[0] == r && s.border_color[1] == g && s.border_color[2] == b && s.border_color[3] == a;
  };
  if (is(0, 0, 0, 0)) return VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
  if (is(0, 0, 0, 1)) return VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK;
  if (is(1, 1, 1, 1)) return VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
  return std::unexpected(backend_error(
      "border colour (" + std::to_string(s.border_color[0]) + ", " + std::to_string(s.border_color[1]) + ", " +
      std::to_string(s.border_color[2]) + ", " + std::to_string(s.border_color[3]) +
      ") is none of Vulkan's fixed ones, (0,0,0,0), (0,0,0,1), (1,1,1,1) (custom border colours need "
      "VK_EXT_custom_border_color, which the backend does not enable)"));
}

bool uses_border(const SamplerSettings& s) {
  return s.address_u == AddressMode::border || s.address_v == AddressMode::border || s.address_w == AddressMode::border;
}

bool uses_linear(const SamplerSettings& s) {
  return s.min_filter == TextureFilter::linear || s.mag_filter == TextureFilter::linear ||
         s.mip_filter == MipFilter::linear;
}

Result<void> check_format_support(const VulkanDevice& device, const Texture& t, bool linear) {
  const VkFormat format = texture_format(t.format);
  VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
  if (linear) needed |= VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  VkFormatProperties props;
  vkGetPhysicalDeviceFormatProperties(device.physical_device(), format, &props);
  if ((props.optimalTilingFeatures & needed) == needed) return {};
  std::string missing;
  const auto note = [&](VkFormatFeatureFlags bit, const char* name) {
    if ((needed & bit) && !(props.optimalTilingFeatures & bit))
      missing += std::string(missing.empty() ? "" : ", ") + name;
  };
  note(VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT, "sampling");
  note(VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT, "linear filtering");
  note(VK_FORMAT_FEATURE_TRANSFER_DST_BIT, "transfer destination");
  return std::unexpected(backend_error(std::string(device.properties().deviceName) + " cannot use " +
                                       to_string(t.format) + " optimal-tiling images for texture '" + t.name +
                                       "' (no " + missing + ")"));
}

VkSamplerAddressMode address_mode(AddressMode a) {
  switch (a) {
    case AddressMode::wrap: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    case AddressMode::mirror: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    case AddressMode::clamp: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case AddressMode::border: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
  }
  return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
}

VkFilter filter(TextureFilter f) { return f == TextureFilter::nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR; }

Result<OwnedSampler> create_sampler(VkDevice device, const SamplerSettings& s) {
  // The defaults are the book's LUT sampling (D3DTEXF_LINEAR, D3DTADDRESS_CLAMP, one
  // level): bilinear or trilinear within level 0, texel centres at (i + 0.5) / size.
  // Without a mip filter only level 0 is read (maxLod 0), as D3DTEXF_NONE does.
  const VkBorderColor border = uses_border(s) ? *border_color(s) : VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
  const VkSamplerCreateInfo info{.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
                                 .magFilter = filter(s.mag_filter),
                                 .minFilter = filter(s.min_filter),
                                 .mipmapMode = s.mip_filter == MipFilter::linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR
                                                                                 : VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                 .addressModeU = address_mode(s.address_u),
                                 .addressModeV = address_mode(s.address_v),
                                 .addressModeW = address_mode(s.address_w),
                                 .mipLodBias = 0.0f,
                                 .anisotropyEnable = VK_FALSE,
                                 .maxAnisotropy = 1.0f,
                                 .compareEnable = VK_FALSE,
                                 .compareOp = VK_COMPARE_OP_ALWAYS,
                                 .minLod = 0.0f,
                                 .maxLod = s.mip_filter == MipFilter::none ? 0.0f : VK_LOD_CLAMP_NONE,
                                 .borderColor = border,
                                 .unnormalizedCoordinates = VK_FALSE};
  VkSampler sampler;
  if (auto ok = check(vkCreateSampler(device, &info, nullptr, &sampler), "vkCreateSampler"); !ok)
    return std::unexpected(ok.error());
  return OwnedSampler(device, sampler);
}

VkImageType image_type(uint32_t dimensions) {
  return dimensions == 1 ? VK_IMAGE_TYPE_1D : dimensions == 2 ? VK_IMAGE_TYPE_2D : VK_IMAGE_TYPE_3D;
}

VkImageViewType view_type(const Texture& t) {
  if (t.cube) return VK_IMAGE_VIEW_TYPE_CUBE;
  return t.dimensions == 1 ? VK_IMAGE_VIEW_TYPE_1D : t.dimensions == 2 ? VK_IMAGE_VIEW_TYPE_2D : VK_IMAGE_VIEW_TYPE_3D;
}

uint32_t layers(const Texture& t) { return t.cube ? 6 : 1; }
size_t bytes_per_value(TexelFormat f) { return f == TexelFormat::rgba8_unorm || f == TexelFormat::rgba8_srgb ? 1 : 4; }

// Every level, one after the other, in the device format: floats as they are, 8-bit
// formats as round(v * 255) (the loader stored the file's bytes / 255, so this is exact).
std::vector<std::byte> texel_bytes(const Texture& t) {
  std::vector<std::byte> bytes;
  for (uint32_t level = 0; level < level_count(t); ++level) {
    const std::vector<float>& values = level == 0 ? t.texels : t.mip_levels[level - 1];
    if (bytes_per_value(t.format) == 4) {
      const auto* raw = reinterpret_cast<const std::byte*>(values.data());
      bytes.insert(bytes.end(), raw, raw + values.size() * sizeof(float));
    } else {
      for (float v : values) bytes.push_back(std::byte(uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f))));
    }
  }
  return bytes;
}

}  // namespace

VkFormat texture_format(TexelFormat format) {
  switch (format) {
    case TexelFormat::r32_float: return VK_FORMAT_R32_SFLOAT;
    case TexelFormat::rgba32_float: return VK_FORMAT_R32G32B32A32_SFLOAT;
    case TexelFormat::rgba8_unorm: return VK_FORMAT_R8G8B8A8_UNORM;
    case TexelFormat::rgba8_srgb: return VK_FORMAT_R8G8B8A8_SRGB;
  }
  return VK_FORMAT_UNDEFINED;
}

Result<std::vector<ResolvedTexture>> resolve_textures(const VulkanDevice& device,
                                                      const std::vector<SamplerBinding>& samplers,
                                                      const TextureResolver* resolver) {
  std::vector<ResolvedTexture> resolved;
  if (samplers.empty()) return resolved;
  if (resolver == nullptr)
    return std::unexpected(backend_error("the program declares " + where(samplers.front()) +
                                         " but the draw has no textures (DrawJob::textures is null)"));
  const auto with_context = [&](const SamplerBinding& sampler, Error e) {
    if (e.message.find("'" + sampler.name + "'") == std::string::npos) e.message = where(sampler) + ": " + e.message;
    return std::unexpected(std::move(e).in_stage(ErrorStage::vulkan));
  };
  for (const SamplerBinding& sampler : samplers) {
    ResolvedTexture r{.sampler = sampler};
    if (has_texture(sampler)) {
      auto texture = resolver->texture(sampler);
      if (!texture) return with_context(sampler, std::move(texture.error()));
      if (*texture == nullptr)
        return std::unexpected(backend_error(where(sampler) + ": the texture resolver returned no texture"));
      if (auto ok = check_texture(device, sampler, **texture); !ok) return std::unexpected(ok.error());
      r.texture = *texture;
    }
    if (has_settings(sampler)) {
      auto settings = resolver->settings(sampler);
      if (!settings) return with_context(sampler, std::move(settings.error()));
      if (uses_border(*settings))
        if (auto border = border_color(*settings); !border) return with_context(sampler, std::move(border.error()));
      r.settings = *settings;
    }
    resolved.push_back(std::move(r));
  }
  return resolved;
}

Result<DrawTextures> DrawTextures::create(const VulkanDevice& device, const std::vector<ResolvedTexture>& textures) {
  DrawTextures out;
  if (textures.empty()) return out;
  const VkPhysicalDeviceLimits& limits = device.properties().limits;
  // Every descriptor is visible to both stages, so each counts against both stages' limits.
  const auto count = [&](bool (*has)(const SamplerBinding&)) {
    return size_t(std::ranges::count_if(textures, [&](const ResolvedTexture& r) { return has(r.sampler); }));
  };
  const size_t images = count(has_texture), samplers = count(has_settings);
  if (images > limits.maxPerStageDescriptorSampledImages || samplers > limits.maxPerStageDescriptorSamplers)
    return std::unexpected(backend_error("the program declares " + std::to_string(images) + " textures and " +
                                         std::to_string(samplers) + " samplers; the device allows " +
                                         std::to_string(limits.maxPerStageDescriptorSampledImages) + " and " +
                                         std::to_string(limits.maxPerStageDescriptorSamplers) + " per stage"));
  // A format needs linear filtering when any sampler reading it filters linearly; a
  // separate image is checked against every sampler setting of the draw (which sampler
  // state reads which image is decided by the shader, not by the descriptors).
  const bool any_linear = std::ranges::any_of(
      textures, [](const ResolvedTexture& r) { return has_settings(r.sampler) && uses_linear(r.settings); });
  for (const ResolvedTexture& r : textures)
    if (r.texture)
      if (auto ok = check_format_support(device, *r.texture,
                                         r.sampler.kind == SamplerKind::combined ? uses_linear(r.settings) : any_linear);
          !ok)
        return std::unexpected(ok.error());

  VkDevice dev = device.device();
  std::map<const Texture*, size_t> uploaded;  // one image per distinct texture
  for (const ResolvedTexture& r : textures) {
    TextureDescriptor descriptor{.set = r.sampler.set, .binding = r.sampler.binding};
    descriptor.type = r.sampler.kind == SamplerKind::combined ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER
                      : r.sampler.kind == SamplerKind::image  ? VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE
                                                              : VK_DESCRIPTOR_TYPE_SAMPLER;
    if (has_settings(r.sampler)) {
      auto same = std::ranges::find(out.samplers_, r.settings, &std::pair<SamplerSettings, OwnedSampler>::first);
      if (same == out.samplers_.end()) {
        auto sampler = create_sampler(dev, r.settings);
        if (!sampler) return std::unexpected(sampler.error());
        out.samplers_.emplace_back(r.settings, std::move(*sampler));
        same = out.samplers_.end() - 1;
      }
      descriptor.sampler = same->second.get();
    }
    if (r.texture) {
      auto [slot, is_new] = uploaded.try_emplace(r.texture, out.images_.size());
      if (is_new) {
        const Texture& t = *r.texture;
        const std::vector<std::byte> bytes = texel_bytes(t);
        auto staging = HostBuffer::create(device, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        if (!staging) return std::unexpected(staging.error());
        staging->write(bytes);

        Image image;
        image.texture = &t;
        const VkImageCreateInfo info{.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                                     .flags = t.cube ? VkImageCreateFlags(VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT) : 0u,
                                     .imageType = image_type(t.dimensions),
                                     .format = texture_format(t.format),
                                     .extent = {t.width, t.height, t.depth},
                                     .mipLevels = level_count(t),
                                     .arrayLayers = layers(t),
                                     .samples = VK_SAMPLE_COUNT_1_BIT,
                                     .tiling = VK_IMAGE_TILING_OPTIMAL,
                                     .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                     .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
                                     .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
        VkImage handle;
        if (auto ok = check(vkCreateImage(dev, &info, nullptr, &handle), "vkCreateImage"); !ok)
          return std::unexpected(ok.error());
        image.image = OwnedImage(dev, handle);

        auto memory = bind_device_memory(device, handle);
        if (!memory) return std::unexpected(memory.error());
        image.memory = std::move(*memory);

        const VkImageViewCreateInfo view_info{
            .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
            .image = handle,
            .viewType = view_type(t),
            .format = texture_format(t.format),
            .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, level_count(t), 0, layers(t)}};
        VkImageView view;
        if (auto ok = check(vkCreateImageView(dev, &view_info, nullptr, &view), "vkCreateImageView"); !ok)
          return std::unexpected(ok.error());
        image.view = OwnedImageView(dev, view);

        out.images_.push_back(std::move(image));
        out.staging_.push_back(std::move(*staging));
      }
      descriptor.view = out.images_[slot->second].view.get();
    }
    out.descriptors_.push_back(descriptor);
  }
  return out;
}

void DrawTextures::record_uploads(VkCommandBuffer commands) const {
  std::vector<VkImageMemoryBarrier> to_transfer, to_shader;
  for (const Image& image : images_) {
    const VkImageSubresourceRange whole{VK_IMAGE_ASPECT_COLOR_BIT, 0, level_count(*image.texture), 0,
                                        layers(*image.texture)};
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
    // Tightly packed, x fastest, then y, then z (or face): Texture's order is the
    // buffer's, one level after the other.
    const Texture& t = *images_[i].texture;
    std::vector<VkBufferImageCopy> regions;
    VkDeviceSize offset = 0;
    for (uint32_t level = 0; level < level_count(t); ++level) {
      const LevelExtent e = level_extent(t, level);
      regions.push_back({.bufferOffset = offset,
                         .bufferRowLength = 0,
                         .bufferImageHeight = 0,
                         .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, layers(t)},
                         .imageOffset = {0, 0, 0},
                         .imageExtent = {e.width, e.height, e.depth}});
      offset += level_values(t, level) * bytes_per_value(t.format);
    }
    vkCmdCopyBufferToImage(commands, staging_[i].buffer(), images_[i].image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           uint32_t(regions.size()), regions.data());
  }
  vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 0, nullptr, 0,
                       nullptr, uint32_t(to_shader.size()), to_shader.data());
}

}  // namespace shaderbed::vulkan
