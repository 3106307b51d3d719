#pragma once
// Maps a vertex-shader input to one of the mesh's attribute streams, first rule that
// applies: the case's explicit map (`[attributes.<language>]`, by input name, then by
// "location N"), the HLSL/Cg semantic when the compiler kept it (POSITION, NORMAL,
// TANGENT, BINORMAL, TEXCOORD0, COLOR/COLOR0), else the variable's name (position, normal,
// tangent, binormal/bitangent, texcoord/uv, color/colour, with common prefixes such as
// in/a_/attr stripped).
#include <cstdint>
#include <vector>

#include "compile/ShaderModule.h"
#include "core/Error.h"
#include "pipeline/Mesh.h"

namespace shaderbed {

enum class VertexAttribute { position, normal, tangent, binormal, texcoord, color, extra };

struct AttributeStream {
  VertexAttribute attribute;
  uint32_t offset;       // bytes into shaderbed::Vertex, or into a vertex's extra streams
  uint32_t components;   // floats stored in the mesh (2, 3 or 4); the driver fills w = 1
  uint32_t binding = 0;  // 0: the Vertex buffer; 1: the mesh's extra streams
};

// The stream for one input; `map` and `extra` (the mesh's extra streams) may be null.
Result<AttributeStream> attribute_stream_for(const StageInput& input, const AttributeTable* map = nullptr,
                                             const ExtraStreams* extra = nullptr);

// One stream per input, in order. The error lists every input that matches no stream,
// with a hint to map it in [attributes.<language>].
Result<std::vector<AttributeStream>> attribute_streams_for(const std::vector<StageInput>& inputs,
                                                           const AttributeTable* map, Language language,
                                                           const ExtraStreams* extra = nullptr);

}  // namespace shaderbed
