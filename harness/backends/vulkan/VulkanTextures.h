#pragma once
// Lookup textures for the samplers a program declares: each reflected combined
// image-sampler is mapped to one of the job's textures through the TextureResolver,
// checked (dimensions, texel count, device limits), uploaded as R32_SFLOAT through a
// staging buffer, and sampled with linear filtering, no mipmaps and clamp-to-edge.
// Everything lives for one draw: LUTs are small and cases rarely share them.
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "backends/Backend.h"
#include "backends/vulkan/VulkanDevice.h"
#include "backends/vulkan/VulkanHandles.h"
#include "backends/vulkan/VulkanMemory.h"
#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed::vulkan {

inline constexpr VkFormat texture_format = VK_FORMAT_R32_SFLOAT;

// The union of both stages' samplers, sorted by (set, binding). A sampler both stages
// declare at one set/binding must agree on name and dimensions; a sampler at the
// set/binding of a uniform block is an error (one descriptor cannot be both).
Result<std::vector<SamplerBinding>> program_samplers(const CompiledProgram& program,
                                                     const std::vector<UniformBlock>& blocks);

struct ResolvedTexture {
  SamplerBinding sampler;
  const Texture* texture = nullptr;
};

// Asks the resolver for every sampler's texture and checks it fits the sampler and the
// device, before any Vulkan object exists. Errors name the sampler (and keep the
// resolver's stage and message when it is the resolver that fails).
Result<std::vector<ResolvedTexture>> resolve_textures(const VulkanDevice& device,
                                                      const std::vector<SamplerBinding>& samplers,
                                                      const TextureResolver* resolver);

// What a descriptor write needs for one combined image-sampler.
struct TextureDescriptor {
  uint32_t set = 0;
  uint32_t binding = 0;
  VkImageView view = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
};

// One sampled image per distinct texture of the draw (a texture bound to two samplers
// is uploaded once) and the one sampler object they all use.
class DrawTextures {
 public:
  static Result<DrawTextures> create(const VulkanDevice& device, const std::vector<ResolvedTexture>& textures);

  bool empty() const { return images_.empty(); }
  // Staging buffer -> image copies with the layout transitions around them; the images
  // end in SHADER_READ_ONLY_OPTIMAL, visible to vertex and fragment shader reads.
  void record_uploads(VkCommandBuffer commands) const;
  // Once the upload submission has completed.
  void release_staging() { staging_.clear(); }
  std::span<const TextureDescriptor> descriptors() const { return descriptors_; }

 private:
  struct Image {
    OwnedMemory memory;
    OwnedImage image;
    OwnedImageView view;
    VkExtent3D extent{};
  };
  // Destroyed in reverse: descriptors refer to views and the sampler, which go last.
  OwnedSampler sampler_;
  std::vector<Image> images_;
  std::vector<HostBuffer> staging_;   // staging_[i] holds images_[i]'s texels until uploaded
  std::vector<TextureDescriptor> descriptors_;
};

}  // namespace shaderbed::vulkan
