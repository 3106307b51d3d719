#pragma once
// The pipeline's vertex input: one interleaved binding of shaderbed::Vertex, and one
// attribute per input the vertex shader declares, fed from the matching mesh stream.
#include <vector>

#include <vulkan/vulkan.h>

#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed::vulkan {

struct VertexInputLayout {
  VkVertexInputBindingDescription binding{};
  std::vector<VkVertexInputAttributeDescription> attributes;
};

// Error naming the input when a vertex shader input is not one of the mesh's streams.
Result<VertexInputLayout> vertex_input_layout(const Reflection& vertex_reflection);

}  // namespace shaderbed::vulkan
