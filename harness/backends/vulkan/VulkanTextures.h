#pragma once
// Textures and sampler objects for the descriptors a program declares: combined
// image-samplers (GLSL, DX9 sampler2D), and HLSL SM4's separate images (Texture2D) and
// samplers (SamplerState). Each image descriptor is mapped to one of the job's textures
// and each sampler descriptor to its SamplerSettings through the TextureResolver,
// checked (dimensions, cube, texel count, device limits and format features), uploaded
// with every mip level through a staging buffer, and sampled as the settings say
// (filter, mip filter, address modes, border colour; sRGB through the image format).
// Everything lives for one draw: textures are small and cases rarely share them.
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "backends/Backend.h"
#include "backends/ProgramBindings.h"
#include "backends/vulkan/VulkanDevice.h"
#include "backends/vulkan/VulkanHandles.h"
#include "backends/vulkan/VulkanMemory.h"
#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed::vulkan {

VkFormat texture_format(TexelFormat format);

struct ResolvedTexture {
  SamplerBinding sampler;
  const Texture* texture = nullptr;   // null for a separate sampler state
  SamplerSettings settings;           // unused for a separate image
};

// Asks the resolver for every descriptor's texture and settings and checks they fit the
// sampler and the device, before any Vulkan object exists. Errors name the sampler (and
// keep the resolver's stage and message when it is the resolver that fails).
Result<std::vector<ResolvedTexture>> resolve_textures(const VulkanDevice& device,
                                                      const std::vector<SamplerBinding>& samplers,
                                                      const TextureResolver* resolver);

// What a descriptor write needs for one texture descriptor.
struct TextureDescriptor {
  uint32_t set = 0;
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  VkImageView view = VK_NULL_HANDLE;    // null for VK_DESCRIPTOR_TYPE_SAMPLER
  VkSampler sampler = VK_NULL_HANDLE;   // null for VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE
};

// One sampled image per distinct texture of the draw (a texture bound to two samplers
// is uploaded once) and one sampler object per distinct SamplerSettings.
class DrawTextures {
 public:
  static Result<DrawTextures> create(const VulkanDevice& device, const std::vector<ResolvedTexture>& textures);

  bool empty() const { return images_.empty(); }
  // Staging buffer -> image copies (every level and face) with the layout transitions
  // around them; the images end in SHADER_READ_ONLY_OPTIMAL, visible to vertex and
  // fragment shader reads.
  void record_uploads(VkCommandBuffer commands) const;
  // Once the upload submission has completed.
  void release_staging() { staging_.clear(); }
  std::span<const TextureDescriptor> descriptors() const { return descriptors_; }

 private:
  struct Image {
    OwnedMemory memory;
    OwnedImage image;
    OwnedImageView view;
    const Texture* texture = nullptr;
  };
  // Destroyed in reverse: descriptors refer to views and samplers, which go last.
  std::vector<std::pair<SamplerSettings, OwnedSampler>> samplers_;
  std::vector<Image> images_;
  std::vector<HostBuffer> staging_;   // staging_[i] holds images_[i]'s texels until uploaded
  std::vector<TextureDescriptor> descriptors_;
};

}  // namespace shaderbed::vulkan
