#include "backends/vulkan/VulkanVertexInput.h"

#include <string>

#include "backends/VertexInputs.h"
#include "backends/vulkan/VulkanResult.h"
#include "pipeline/Mesh.h"

namespace shaderbed::vulkan {

Result<VertexInputLayout> vertex_input_layout(const Reflection& vertex_reflection, const AttributeTable* attributes,
                                              Language language, const ExtraStreams* extra) {
  VertexInputLayout layout;
  layout.bindings.push_back({.binding = 0, .stride = sizeof(Vertex), .inputRate = VK_VERTEX_INPUT_RATE_VERTEX});
  auto streams = attribute_streams_for(vertex_reflection.inputs, attributes, language, extra);
  if (!streams) return std::unexpected(std::move(streams.error()));
  for (size_t i = 0; i < streams->size(); ++i) {
    const StageInput& input = vertex_reflection.inputs[i];
    const AttributeStream& stream = (*streams)[i];
    for (const auto& existing : layout.attributes)
      if (existing.location == input.location)
        return std::unexpected(backend_error("two vertex inputs at location " + std::to_string(input.location)));
    // Fewer components than the shader reads is fine: Vulkan fills y/z with 0 and w with 1.
    VkFormat format;
    switch (stream.components) {
      case 2: format = VK_FORMAT_R32G32_SFLOAT; break;
      case 3: format = VK_FORMAT_R32G32B32_SFLOAT; break;
      case 4: format = VK_FORMAT_R32G32B32A32_SFLOAT; break;
      default:
        return std::unexpected(backend_error("vertex input '" + input.name + "' maps to a mesh stream of " +
                                             std::to_string(stream.components) + " floats"));
    }
    if (stream.binding == 1 && layout.bindings.size() == 1)
      layout.bindings.push_back({.binding = 1,
                                 .stride = uint32_t(extra->stride_floats() * sizeof(float)),
                                 .inputRate = VK_VERTEX_INPUT_RATE_VERTEX});
    layout.attributes.push_back(
        {.location = input.location, .binding = stream.binding, .format = format, .offset = stream.offset});
  }
  return layout;
}

}  // namespace shaderbed::vulkan
