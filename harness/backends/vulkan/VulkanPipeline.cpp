#include "backends/vulkan/VulkanPipeline.h"

#include <array>
#include <cstring>
#include <string>
#include <vector>

#include "backends/vulkan/VulkanResult.h"

namespace shaderbed::vulkan {
namespace {

constexpr uint32_t spirv_magic = 0x07230203;

std::string entry_point(const ShaderModule& module) {
  return module.entry_point.empty() ? "main" : module.entry_point;
}

const char* stage_name(Stage stage) { return stage == Stage::vertex ? "vertex" : "fragment"; }

// Whether the module has an OpEntryPoint of this stage and name. Checked up front
// because a pipeline naming a missing entry point is undefined behaviour, not an error
// code: drivers may crash on it.
bool has_entry_point(const std::vector<uint32_t>& spirv, Stage stage, const std::string& name) {
  constexpr uint32_t op_entry_point = 15;
  constexpr uint32_t header_words = 5;
  const uint32_t execution_model = stage == Stage::vertex ? 0 : 4;  // Vertex, Fragment
  for (size_t at = header_words; at < spirv.size();) {
    const uint32_t word_count = spirv[at] >> 16;
    const uint32_t opcode = spirv[at] & 0xffff;
    if (word_count == 0 || at + word_count > spirv.size()) return false;
    if (opcode == op_entry_point && word_count >= 4 && spirv[at + 1] == execution_model) {
      // The name is a nul-terminated UTF-8 literal packed little-endian from word 3.
      const auto* chars = reinterpret_cast<const char*>(&spirv[at + 3]);
      const size_t max_chars = size_t(word_count - 3) * sizeof(uint32_t);
      if (std::string(chars, strnlen(chars, max_chars)) == name) return true;
    }
    at += word_count;
  }
  return false;
}

Result<OwnedShaderModule> create_shader_module(VkDevice device, const ShaderModule& module, Stage expected) {
  auto fail_here = [&](std::string message) {
    return std::unexpected(backend_error(std::move(message)).in_file(module.source_file));
  };
  if (module.stage != expected)
    return fail_here(std::string("the program's ") + stage_name(expected) + " module is a " + stage_name(module.stage) +
                     " shader");
  if (module.spirv.empty() || module.spirv.front() != spirv_magic)
    return fail_here(std::string("the ") + stage_name(expected) + " module has no SPIR-V for the Vulkan target");
  if (!has_entry_point(module.spirv, expected, entry_point(module)))
    return fail_here(std::string("the ") + stage_name(expected) + " SPIR-V has no " + stage_name(expected) +
                     " entry point '" + entry_point(module) + "'");
  const VkShaderModuleCreateInfo info{.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                      .codeSize = module.spirv.size() * sizeof(uint32_t),
                                      .pCode = module.spirv.data()};
  VkShaderModule handle;
  if (VkResult r = vkCreateShaderModule(device, &info, nullptr, &handle); r != VK_SUCCESS)
    return std::unexpected(vulkan_error("vkCreateShaderModule", r).in_file(module.source_file));
  return OwnedShaderModule(device, handle);
}

}  // namespace

Result<GraphicsPipeline> GraphicsPipeline::create(const VulkanDevice& device, VkRenderPass render_pass,
                                                  const CompiledProgram& program, const VertexInputLayout& vertex_input,
                                                  std::span<const VkDescriptorSetLayout> set_layouts) {
  VkDevice dev = device.device();
  auto vertex_module = create_shader_module(dev, program.vertex, Stage::vertex);
  if (!vertex_module) return std::unexpected(vertex_module.error());
  auto fragment_module = create_shader_module(dev, program.fragment, Stage::fragment);
  if (!fragment_module) return std::unexpected(fragment_module.error());

  GraphicsPipeline out;
  const VkPipelineLayoutCreateInfo layout_info{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                               .setLayoutCount = uint32_t(set_layouts.size()),
                                               .pSetLayouts = set_layouts.data()};
  VkPipelineLayout layout;
  if (auto ok = check(vkCreatePipelineLayout(dev, &layout_info, nullptr, &layout), "vkCreatePipelineLayout"); !ok)
    return std::unexpected(ok.error());
  out.layout_ = OwnedPipelineLayout(dev, layout);

  const std::string vertex_entry = entry_point(program.vertex);
  const std::string fragment_entry = entry_point(program.fragment);
  const std::array stages{
      VkPipelineShaderStageCreateInfo{.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                                      .stage = VK_SHADER_STAGE_VERTEX_BIT,
                                      .module = vertex_module->get(),
                                      .pName = vertex_entry.c_str()},
      VkPipelineShaderStageCreateInfo{.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                                      .stage = VK_SHADER_STAGE_FRAGMENT_BIT,
                                      .module = fragment_module->get(),
                                      .pName = fragment_entry.c_str()},
  };
  const VkPipelineVertexInputStateCreateInfo vertex_input_state{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
      .vertexBindingDescriptionCount = 1,
      .pVertexBindingDescriptions = &vertex_input.binding,
      .vertexAttributeDescriptionCount = uint32_t(vertex_input.attributes.size()),
      .pVertexAttributeDescriptions = vertex_input.attributes.data()};
  const VkPipelineInputAssemblyStateCreateInfo input_assembly{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
      .topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST};
  // Viewport and scissor are dynamic: the pipeline does not depend on the target size.
  const VkPipelineViewportStateCreateInfo viewport_state{.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
                                                         .viewportCount = 1,
                                                         .scissorCount = 1};
  // No culling: shaderbed compares every covered pixel, whichever way a triangle winds.
  const VkPipelineRasterizationStateCreateInfo rasterization{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
      .polygonMode = VK_POLYGON_MODE_FILL,
      .cullMode = VK_CULL_MODE_NONE,
      .frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE,
      .lineWidth = 1.0f};
  const VkPipelineMultisampleStateCreateInfo multisample{.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
                                                         .rasterizationSamples = VK_SAMPLE_COUNT_1_BIT};
  const VkPipelineDepthStencilStateCreateInfo depth_stencil{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
      .depthTestEnable = VK_TRUE,
      .depthWriteEnable = VK_TRUE,
      .depthCompareOp = VK_COMPARE_OP_LESS};
  // No blending: the attachment receives the shader's output bits unchanged.
  const VkPipelineColorBlendAttachmentState blend_attachment{
      .blendEnable = VK_FALSE,
      .colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                        VK_COLOR_COMPONENT_A_BIT};
  const VkPipelineColorBlendStateCreateInfo blend{.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
                                                  .attachmentCount = 1,
                                                  .pAttachments = &blend_attachment};
  const std::array dynamic_states{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  const VkPipelineDynamicStateCreateInfo dynamic{.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
                                                 .dynamicStateCount = uint32_t(dynamic_states.size()),
                                                 .pDynamicStates = dynamic_states.data()};
  const VkGraphicsPipelineCreateInfo info{.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
                                          .stageCount = uint32_t(stages.size()),
                                          .pStages = stages.data(),
                                          .pVertexInputState = &vertex_input_state,
                                          .pInputAssemblyState = &input_assembly,
                                          .pViewportState = &viewport_state,
                                          .pRasterizationState = &rasterization,
                                          .pMultisampleState = &multisample,
                                          .pDepthStencilState = &depth_stencil,
                                          .pColorBlendState = &blend,
                                          .pDynamicState = &dynamic,
                                          .layout = layout,
                                          .renderPass = render_pass,
                                          .subpass = 0};
  VkPipeline pipeline;
  if (VkResult r = vkCreateGraphicsPipelines(dev, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline); r != VK_SUCCESS)
    return std::unexpected(vulkan_error("vkCreateGraphicsPipelines", r));
  out.pipeline_ = OwnedPipeline(dev, pipeline);
  return out;
}

}  // namespace shaderbed::vulkan
