#include "GlTestSupport.h"

#include <memory>

#include "compile/Compiler.h"

namespace shaderbed::gl_test {

Result<Backend*> gl_backend() {
  static Result<std::unique_ptr<Backend>> backend = make_gl_backend();
  if (!backend) return std::unexpected(backend.error());
  return backend->get();
}

Mesh ndc_rectangle(float x0, float y0, float x1, float y1, float z) {
  Mesh mesh;
  mesh.name = "ndc rectangle";
  const glm::vec3 normal(0, 0, 1), tangent(1, 0, 0);
  mesh.vertices = {
      {{x0, y0, z}, normal, tangent, {0, 0}},
      {{x1, y0, z}, normal, tangent, {1, 0}},
      {{x1, y1, z}, normal, tangent, {1, 1}},
      {{x0, y1, z}, normal, tangent, {0, 1}},
  };
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

Result<CompiledProgram> compile_glsl(const std::string& vertex, const std::string& fragment) {
  ProgramSource source;
  source.language = Language::glsl;
  source.vertex = ShaderSource{.stage = Stage::vertex, .path = "test.vert", .text = vertex, .entry_point = "main"};
  source.fragment = ShaderSource{.stage = Stage::fragment, .path = "test.frag", .text = fragment, .entry_point = "main"};
  return compile_program(source);
}

CompiledProgram native_glsl_only(const std::string& vertex, const std::string& fragment,
                                 const std::string& vertex_file, const std::string& fragment_file) {
  CompiledProgram program;
  program.language = Language::glsl;
  program.vertex.stage = Stage::vertex;
  program.vertex.source_file = vertex_file;
  program.fragment.stage = Stage::fragment;
  program.fragment.source_file = fragment_file;
  program.vertex_gl = program.vertex;
  program.fragment_gl = program.fragment;
  program.vertex_native_glsl = vertex;
  program.fragment_native_glsl = fragment;
  return program;
}

const char* const kPassThroughVertex = R"(#version 450
layout(location = 0) in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)";

int coverage_count(const Image& image) {
  int covered = 0;
  for (uint8_t c : image.coverage) covered += c;
  return covered;
}

}  // namespace shaderbed::gl_test
