#pragma once
// Maps a vertex-shader input to one of the mesh's attribute streams: by HLSL semantic
// when the compiler kept it, else by the variable's name (position, normal, tangent,
// texcoord/uv, with common prefixes such as in/a_/attr stripped).
#include <cstdint>

#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed {

enum class VertexAttribute { position, normal, tangent, texcoord };

struct AttributeStream {
  VertexAttribute attribute;
  uint32_t offset;       // bytes into shaderbed::Vertex
  uint32_t components;   // floats stored in the mesh (3 or 2); the driver fills w = 1
};

Result<AttributeStream> attribute_stream_for(const StageInput& input);

}  // namespace shaderbed
