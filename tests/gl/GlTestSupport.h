#pragma once
// Shared pieces of the GL backend tests: one real OSMesa backend per test binary,
// NDC-space meshes, and small shader pairs compiled by the real compile stage.
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "MapResolvers.h"
#include "backends/Backend.h"

namespace shaderbed {
// Readable parameter names in GoogleTest output ("spirv", not "4-byte object").
inline void PrintTo(ShaderPath path, std::ostream* out) { *out << to_string(path); }
}  // namespace shaderbed

namespace shaderbed::gl_test {

// The process-wide GL backend, created on first use; the error when OSMesa is unusable.
Result<Backend*> gl_backend();

using test::MapResolver;
using test::MapTextureResolver;

// Two triangles covering x0..x1, y0..y1 in NDC at depth z, with normals (0,0,1) and uv.
Mesh ndc_rectangle(float x0, float y0, float x1, float y1, float z = 0.5f);

// GLSL 450 vertex + fragment through the real compile stage (all three GL forms).
Result<CompiledProgram> compile_glsl(const std::string& vertex, const std::string& fragment);

// Only the native-GLSL form, for shaders the SPIR-V front ends reject on purpose (loose
// uniforms, syntax errors) or that must reach Mesa's compiler untouched.
CompiledProgram native_glsl_only(const std::string& vertex, const std::string& fragment,
                                 const std::string& vertex_file = "test.vert",
                                 const std::string& fragment_file = "test.frag");

// A vertex shader that passes NDC positions through.
extern const char* const kPassThroughVertex;

// Covered pixels of an image.
int coverage_count(const Image& image);

// A vertex shader with a Transform block (binding 0) and a fragment shader with a Material
// block (binding 1): uniforms that must reach the shader on every path.
inline const char* const kTransformVertex = R"(#version 450
layout(location = 0) in vec3 position;
layout(binding = 0, std140) uniform Transform { mat4 clip_from_object; };
void main() { gl_Position = clip_from_object * vec4(position, 1.0); }
)";

inline const char* const kMaterialFragment = R"(#version 450
layout(binding = 1, std140) uniform Material { vec4 tint; float scale; };
layout(location = 0) out vec4 colour;
void main() { colour = tint * scale; }
)";

}  // namespace shaderbed::gl_test
