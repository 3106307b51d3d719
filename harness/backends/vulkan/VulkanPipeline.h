#pragma once
// The graphics pipeline of one draw: the program's SPIR-V stages, the mesh vertex
// layout, the uniform descriptor set layouts, and shaderbed's fixed raster state
// (triangle list) with the draw's RenderState: culling, depth, blending, fill mode
// (default: no culling, depth test LESS with writes, no blending, solid).
#include <span>

#include <vulkan/vulkan.h>

#include "backends/vulkan/VulkanDevice.h"
#include "backends/vulkan/VulkanHandles.h"
#include "backends/vulkan/VulkanVertexInput.h"
#include "pipeline/RenderState.h"
#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed::vulkan {

class GraphicsPipeline {
 public:
  // Creates (and, once the pipeline exists, destroys) the shader modules too: all of it
  // is the driver's compile work that build_ms measures.
  static Result<GraphicsPipeline> create(const VulkanDevice& device, VkRenderPass render_pass,
                                         const CompiledProgram& program, const VertexInputLayout& vertex_input,
                                         std::span<const VkDescriptorSetLayout> set_layouts,
                                         const RenderState& state = {});

  VkPipeline pipeline() const { return pipeline_.get(); }
  VkPipelineLayout layout() const { return layout_.get(); }

 private:
  OwnedPipelineLayout layout_;
  OwnedPipeline pipeline_;
};

}  // namespace shaderbed::vulkan
