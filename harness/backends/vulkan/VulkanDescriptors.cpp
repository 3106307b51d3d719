#include "backends/vulkan/VulkanDescriptors.h"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "backends/vulkan/VulkanResult.h"

namespace shaderbed::vulkan {
namespace {

std::string where(const UniformBlock& block) {
  return "uniform block '" + block.name + "' (set " + std::to_string(block.set) + ", binding " +
         std::to_string(block.binding) + ")";
}

}  // namespace

Result<DescriptorBindings> DescriptorBindings::create(const VulkanDevice& device, const std::vector<PackedBlock>& blocks,
                                                     std::span<const TextureDescriptor> textures) {
  VkDevice dev = device.device();
  const VkPhysicalDeviceLimits& limits = device.properties().limits;
  DescriptorBindings out;
  if (blocks.empty() && textures.empty()) return out;

  // Stage flags vertex|fragment for every block: each counts against both stages' limits.
  if (blocks.size() > limits.maxPerStageDescriptorUniformBuffers || blocks.size() > limits.maxDescriptorSetUniformBuffers)
    return std::unexpected(backend_error("the program uses " + std::to_string(blocks.size()) +
                                         " uniform blocks; the device allows " +
                                         std::to_string(limits.maxPerStageDescriptorUniformBuffers)));
  uint32_t set_count = 0;
  for (const PackedBlock& p : blocks) {
    set_count = std::max(set_count, p.block.set + 1);
    if (p.block.set >= limits.maxBoundDescriptorSets)
      return std::unexpected(backend_error(where(p.block) + " uses set " + std::to_string(p.block.set) +
                                           "; the device binds sets 0.." +
                                           std::to_string(limits.maxBoundDescriptorSets - 1)));
    if (p.bytes.size() > limits.maxUniformBufferRange)
      return std::unexpected(backend_error(where(p.block) + " is " + std::to_string(p.bytes.size()) +
                                           " bytes; the device allows " + std::to_string(limits.maxUniformBufferRange)));
  }
  for (const TextureDescriptor& t : textures) {
    set_count = std::max(set_count, t.set + 1);
    if (t.set >= limits.maxBoundDescriptorSets)
      return std::unexpected(backend_error("a sampler at binding " + std::to_string(t.binding) + " uses set " +
                                           std::to_string(t.set) + "; the device binds sets 0.." +
                                           std::to_string(limits.maxBoundDescriptorSets - 1)));
  }

  for (const PackedBlock& p : blocks) {
    auto buffer = HostBuffer::create(device, p.bytes.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    if (!buffer) return std::unexpected(buffer.error());
    buffer->write(p.bytes);
    out.buffers_.push_back(std::move(*buffer));
  }

  constexpr VkShaderStageFlags both_stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
  std::vector<bool> used(set_count, false);
  for (uint32_t set = 0; set < set_count; ++set) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (const PackedBlock& p : blocks)
      if (p.block.set == set)
        bindings.push_back({.binding = p.block.binding,
                            .descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                            .descriptorCount = 1,
                            .stageFlags = both_stages});
    for (const TextureDescriptor& t : textures)
      if (t.set == set)
        bindings.push_back({.binding = t.binding,
                            .descriptorType = t.type,
                            .descriptorCount = 1,
                            .stageFlags = both_stages});
    used[set] = !bindings.empty();
    const VkDescriptorSetLayoutCreateInfo info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                               .bindingCount = uint32_t(bindings.size()),
                                               .pBindings = bindings.data()};
    VkDescriptorSetLayout layout;
    if (auto ok = check(vkCreateDescriptorSetLayout(dev, &info, nullptr, &layout), "vkCreateDescriptorSetLayout"); !ok)
      return std::unexpected(ok.error());
    out.layouts_.emplace_back(dev, layout);
  }

  std::vector<VkDescriptorPoolSize> pool_sizes;
  if (!blocks.empty()) pool_sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, uint32_t(blocks.size())});
  for (VkDescriptorType type : {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE,
                                VK_DESCRIPTOR_TYPE_SAMPLER})
    if (const auto n = std::ranges::count(textures, type, &TextureDescriptor::type); n > 0)
      pool_sizes.push_back({type, uint32_t(n)});
  const VkDescriptorPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                             .maxSets = uint32_t(std::ranges::count(used, true)),
                                             .poolSizeCount = uint32_t(pool_sizes.size()),
                                             .pPoolSizes = pool_sizes.data()};
  VkDescriptorPool pool;
  if (auto ok = check(vkCreateDescriptorPool(dev, &pool_info, nullptr, &pool), "vkCreateDescriptorPool"); !ok)
    return std::unexpected(ok.error());
  out.pool_ = OwnedDescriptorPool(dev, pool);

  out.sets_.assign(set_count, VK_NULL_HANDLE);
  for (uint32_t set = 0; set < set_count; ++set) {
    if (!used[set]) continue;
    const VkDescriptorSetLayout layout = out.layouts_[set].get();
    const VkDescriptorSetAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                            .descriptorPool = pool,
                                            .descriptorSetCount = 1,
                                            .pSetLayouts = &layout};
    if (auto ok = check(vkAllocateDescriptorSets(dev, &alloc, &out.sets_[set]), "vkAllocateDescriptorSets"); !ok)
      return std::unexpected(ok.error());
  }
  std::vector<VkDescriptorBufferInfo> buffer_infos(blocks.size());
  std::vector<VkDescriptorImageInfo> image_infos(textures.size());
  std::vector<VkWriteDescriptorSet> writes;
  for (size_t i = 0; i < blocks.size(); ++i) {
    buffer_infos[i] = {out.buffers_[i].buffer(), 0, VK_WHOLE_SIZE};
    writes.push_back({.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                      .dstSet = out.sets_[blocks[i].block.set],
                      .dstBinding = blocks[i].block.binding,
                      .descriptorCount = 1,
                      .descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                      .pBufferInfo = &buffer_infos[i]});
  }
  for (size_t i = 0; i < textures.size(); ++i) {
    image_infos[i] = {textures[i].sampler, textures[i].view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    writes.push_back({.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                      .dstSet = out.sets_[textures[i].set],
                      .dstBinding = textures[i].binding,
                      .descriptorCount = 1,
                      .descriptorType = textures[i].type,
                      .pImageInfo = &image_infos[i]});
  }
  vkUpdateDescriptorSets(dev, uint32_t(writes.size()), writes.data(), 0, nullptr);
  return out;
}

std::vector<VkDescriptorSetLayout> DescriptorBindings::set_layouts() const {
  std::vector<VkDescriptorSetLayout> layouts;
  for (const auto& layout : layouts_) layouts.push_back(layout.get());
  return layouts;
}

void DescriptorBindings::bind(VkCommandBuffer commands, VkPipelineLayout pipeline_layout) const {
  for (uint32_t set = 0; set < sets_.size(); ++set)
    if (sets_[set] != VK_NULL_HANDLE)
      vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_layout, set, 1, &sets_[set], 0, nullptr);
}

}  // namespace shaderbed::vulkan
