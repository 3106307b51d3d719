#pragma once
// The pipeline's vertex input: one interleaved binding of shaderbed::Vertex, and one
// attribute per input the vertex shader declares, fed from the matching mesh stream.
#include <vector>

#include <vulkan/vulkan.h>

#include "compile/ShaderModule.h"
#include "core/Error.h"
#include "pipeline/Mesh.h"

namespace shaderbed::vulkan {

struct VertexInputLayout {
  // Binding 0: shaderbed::Vertex; binding 1 when an input reads the mesh's extra streams.
  std::vector<VkVertexInputBindingDescription> bindings;
  std::vector<VkVertexInputAttributeDescription> attributes;
};

// Error naming every vertex shader input that is not one of the mesh's streams;
// `attributes` is the case's [attributes.<language>] map (may be null).
Result<VertexInputLayout> vertex_input_layout(const Reflection& vertex_reflection, const AttributeTable* attributes,
                                              Language language, const ExtraStreams* extra = nullptr);

}  // namespace shaderbed::vulkan
