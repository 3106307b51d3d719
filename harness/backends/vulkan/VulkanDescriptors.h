#pragma once
// Uniform blocks and textures -> descriptor sets: the blocks of both stages are
// merged by (set, binding), each is packed from the UniformResolver into its own
// host-visible uniform buffer, textures (VulkanTextures) become combined image-samplers,
// sampled images or samplers in the same sets, and every used set gets a layout, a
// descriptor set and its writes.
#include <cstddef>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "backends/ProgramBindings.h"
#include "backends/vulkan/VulkanDevice.h"
#include "backends/vulkan/VulkanHandles.h"
#include "backends/vulkan/VulkanMemory.h"
#include "backends/vulkan/VulkanTextures.h"
#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed::vulkan {

class DescriptorBindings {
 public:
  // `textures` must not share a set/binding with a block (program_samplers checks).
  static Result<DescriptorBindings> create(const VulkanDevice& device, const std::vector<PackedBlock>& blocks,
                                           std::span<const TextureDescriptor> textures = {});

  // One layout per set number 0..highest used (unused numbers get an empty layout, as
  // a pipeline layout's sets are numbered by position).
  std::vector<VkDescriptorSetLayout> set_layouts() const;
  void bind(VkCommandBuffer commands, VkPipelineLayout pipeline_layout) const;

 private:
  std::vector<HostBuffer> buffers_;
  std::vector<OwnedDescriptorSetLayout> layouts_;
  OwnedDescriptorPool pool_;                  // frees the sets with it
  std::vector<VkDescriptorSet> sets_;         // by set number; VK_NULL_HANDLE for unused numbers
};

}  // namespace shaderbed::vulkan
