#include "backends/vulkan/VulkanPipeline.h"

#include <array>
#include <string>
#include <vector>

#include "backends/vulkan/VulkanResult.h"
#include "pipeline/SpirvWords.h"

namespace shaderbed::vulkan {
namespace {

std::string entry_point(const ShaderModule& module) {
  return module.entry_point.empty() ? "main" : module.entry_point;
}

const char* stage_name(Stage stage) { return stage == Stage::vertex ? "vertex" : "fragment"; }

// Whether the module has an OpEntryPoint of this stage and name. Checked up front
// because a pipeline naming a missing entry point is undefined behaviour, not an error
// code: drivers may crash on it.
bool has_entry_point(const std::vector<uint32_t>& spirv, Stage stage, const std::string& name) {
  const spv::ExecutionModel model =
      stage == Stage::vertex ? spv::ExecutionModel::Vertex : spv::ExecutionModel::Fragment;
  for (const SpirvInstruction in : SpirvInstructions(spirv))
    if (in.opcode == spv::Op::OpEntryPoint && in.words.size() >= 4 && in.words[1] == std::to_underlying(model) &&
        spirv_literal_string(in.words.subspan(3)) == name)
      return true;
  return false;
}

Result<OwnedShaderModule> create_shader_module(VkDevice device, const ShaderModule& module, Stage expected) {
  auto fail_here = [&](std::string message) {
    return std::unexpected(backend_error(std::move(message)).in_file(module.source_file));
  };
  if (module.stage != expected)
    return fail_here(std::string("the program's ") + stage_name(expected) + " module is a " + stage_name(module.stage) +
                     " shader");
  if (module.spirv.empty() || module.spirv.front() != spv::MagicNumber)
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

VkCompareOp to_vulkan(CompareOp op) {
  switch (op) {
    case CompareOp::never: return VK_COMPARE_OP_NEVER;
    case CompareOp::less: return VK_COMPARE_OP_LESS;
    case CompareOp::equal: return VK_COMPARE_OP_EQUAL;
    case CompareOp::less_equal: return VK_COMPARE_OP_LESS_OR_EQUAL;
    case CompareOp::greater: return VK_COMPARE_OP_GREATER;
    case CompareOp::not_equal: return VK_COMPARE_OP_NOT_EQUAL;
    case CompareOp::greater_equal: return VK_COMPARE_OP_GREATER_OR_EQUAL;
    case CompareOp::always: return VK_COMPARE_OP_ALWAYS;
  }
  return VK_COMPARE_OP_LESS;
}

VkBlendFactor to_vulkan(BlendFactor f) {
  switch (f) {
    case BlendFactor::zero: return VK_BLEND_FACTOR_ZERO;
    case BlendFactor::one: return VK_BLEND_FACTOR_ONE;
    case BlendFactor::src_colour: return VK_BLEND_FACTOR_SRC_COLOR;
    case BlendFactor::inv_src_colour: return VK_BLEND_FACTOR_ONE_MINUS_SRC_COLOR;
    case BlendFactor::src_alpha: return VK_BLEND_FACTOR_SRC_ALPHA;
    case BlendFactor::inv_src_alpha: return VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    case BlendFactor::dest_alpha: return VK_BLEND_FACTOR_DST_ALPHA;
    case BlendFactor::inv_dest_alpha: return VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA;
    case BlendFactor::dest_colour: return VK_BLEND_FACTOR_DST_COLOR;
    case BlendFactor::inv_dest_colour: return VK_BLEND_FACTOR_ONE_MINUS_DST_COLOR;
    case BlendFactor::src_alpha_saturate: return VK_BLEND_FACTOR_SRC_ALPHA_SATURATE;
  }
  return VK_BLEND_FACTOR_ONE;
}

VkBlendOp to_vulkan(BlendOp op) {
  switch (op) {
    case BlendOp::add: return VK_BLEND_OP_ADD;
    case BlendOp::subtract: return VK_BLEND_OP_SUBTRACT;
    case BlendOp::reverse_subtract: return VK_BLEND_OP_REVERSE_SUBTRACT;
    case BlendOp::min: return VK_BLEND_OP_MIN;
    case BlendOp::max: return VK_BLEND_OP_MAX;
  }
  return VK_BLEND_OP_ADD;
}

}  // namespace

Result<GraphicsPipeline> GraphicsPipeline::create(const VulkanDevice& device, VkRenderPass render_pass,
                                                  const CompiledProgram& program, const VertexInputLayout& vertex_input,
                                                  std::span<const VkDescriptorSetLayout> set_layouts,
                                                  const RenderState& state) {
  VkDevice dev = device.device();
  if (state.fill != FillMode::solid && !device.fill_mode_non_solid())
    return std::unexpected(backend_error("FillMode " + std::string(state.fill == FillMode::wireframe ? "WIREFRAME" : "POINT") +
                                         " needs fillModeNonSolid, which this Vulkan device lacks"));
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
      .vertexBindingDescriptionCount = uint32_t(vertex_input.bindings.size()),
      .pVertexBindingDescriptions = vertex_input.bindings.data(),
      .vertexAttributeDescriptionCount = uint32_t(vertex_input.attributes.size()),
      .pVertexAttributeDescriptions = vertex_input.attributes.data()};
  const VkPipelineInputAssemblyStateCreateInfo input_assembly{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
      .topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST};
  // Viewport and scissor are dynamic: the pipeline does not depend on the target size.
  const VkPipelineViewportStateCreateInfo viewport_state{.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
                                                         .viewportCount = 1,
                                                         .scissorCount = 1};
  // By default no culling: shaderbed compares every covered pixel, whichever way a
  // triangle winds. D3D's CullMode names the winding culled as the image is seen; the
  // framebuffer's row 0 is the image's top (negative viewport height), and Vulkan's
  // CLOCKWISE front face is clockwise in exactly those coordinates.
  const VkPipelineRasterizationStateCreateInfo rasterization{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
      .polygonMode = state.fill == FillMode::wireframe ? VK_POLYGON_MODE_LINE
                     : state.fill == FillMode::point   ? VK_POLYGON_MODE_POINT
                                                       : VK_POLYGON_MODE_FILL,
      .cullMode = VkCullModeFlags(state.cull == CullMode::ccw  ? VK_CULL_MODE_BACK_BIT
                                  : state.cull == CullMode::cw ? VK_CULL_MODE_FRONT_BIT
                                                               : VK_CULL_MODE_NONE),
      .frontFace = VK_FRONT_FACE_CLOCKWISE,
      .lineWidth = 1.0f};
  const VkPipelineMultisampleStateCreateInfo multisample{.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
                                                         .rasterizationSamples = VK_SAMPLE_COUNT_1_BIT};
  // Depth is always written: coverage is read from it (RenderState.h).
  const VkPipelineDepthStencilStateCreateInfo depth_stencil{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
      .depthTestEnable = VK_TRUE,
      .depthWriteEnable = VK_TRUE,
      .depthCompareOp = to_vulkan(depth_compare_for_one_draw(state))};
  // Without blending the attachment receives the shader's output bits unchanged.
  const VkPipelineColorBlendAttachmentState blend_attachment{
      .blendEnable = state.blend ? VK_TRUE : VK_FALSE,
      .srcColorBlendFactor = to_vulkan(state.src_blend),
      .dstColorBlendFactor = to_vulkan(state.dest_blend),
      .colorBlendOp = to_vulkan(state.blend_op),
      .srcAlphaBlendFactor = to_vulkan(state.src_blend),
      .dstAlphaBlendFactor = to_vulkan(state.dest_blend),
      .alphaBlendOp = to_vulkan(state.blend_op),
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
