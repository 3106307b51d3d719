#pragma once
// The mesh as GL vertex and index buffers, with one vertex attribute per shader input,
// matched to the mesh's streams by the case's map, semantic or name (attribute_streams_for).
#include <vector>

#include "backends/gl/GlObject.h"
#include "compile/ShaderModule.h"
#include "core/Error.h"
#include "pipeline/Mesh.h"

namespace shaderbed::gl {

struct GlMesh {
  GlVertexArray vertex_array;  // bound, ready for glDrawElements
  GlBuffer vertices;
  GlBuffer indices;
  GlBuffer extra;              // the mesh's extra streams, when an input reads them
  GLsizei index_count = 0;
};

// Rejects meshes that would make the driver read out of bounds (indices past the
// vertex count, a partial triangle) instead of drawing garbage.
// `attributes`: the case's [attributes.<language>] map (may be null).
Result<GlMesh> upload_mesh(const GlFunctions& gl, const Mesh& mesh, const std::vector<StageInput>& inputs,
                           const AttributeTable* attributes = nullptr, Language language = Language::glsl);

}  // namespace shaderbed::gl
