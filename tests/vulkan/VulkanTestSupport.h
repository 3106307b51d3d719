#pragma once
// Shared by the Vulkan backend tests: one real lavapipe backend for the whole test
// binary, GLSL compiled through shaderbed's compile stage, screen-aligned quads placed
// on exact pixel rectangles, and a uniform resolver backed by a name -> floats map.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "MapResolvers.h"
#include "backends/Backend.h"
#include "backends/UniformPacking.h"
#include "compile/Compiler.h"
#include "pipeline/Mesh.h"

namespace shaderbed::vulkan_test {

// Created on first use and kept for the process: creating a device per test would
// dominate the run time, and reuse across draws is itself what the backend promises.
inline Backend* shared_backend() {
  static Result<std::unique_ptr<Backend>> backend = make_vulkan_backend();
  if (!backend) {
    ADD_FAILURE() << "make_vulkan_backend failed: " << backend.error().to_string();
    return nullptr;
  }
  return backend->get();
}

inline Result<CompiledProgram> compile_glsl(const std::string& vertex_source, const std::string& fragment_source) {
  CompiledProgram program;
  program.language = Language::glsl;
  auto vertex = compile_stage(Language::glsl, ShaderSource{.stage = Stage::vertex, .path = "test.vert", .text = vertex_source},
                              Target::vulkan);
  if (!vertex) return std::unexpected(vertex.error());
  auto fragment = compile_stage(
      Language::glsl, ShaderSource{.stage = Stage::fragment, .path = "test.frag", .text = fragment_source}, Target::vulkan);
  if (!fragment) return std::unexpected(fragment.error());
  program.vertex = std::move(*vertex);
  program.fragment = std::move(*fragment);
  return program;
}

// Passes the mesh position straight through as clip space (w = 1 from the driver).
inline const std::string passthrough_vertex_shader = R"(#version 450
layout(location = 0) in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)";

// A fragment shader writing one constant colour, given as a GLSL vec4 expression.
inline std::string constant_fragment_shader(const std::string& colour_expression) {
  return "#version 450\nlayout(location = 0) out vec4 colour;\nvoid main() { colour = " + colour_expression + "; }\n";
}

inline Vertex vertex_at(float x, float y, float z) {
  return Vertex{.position = {x, y, z}, .normal = {0, 0, 1}, .tangent = {1, 0, 0}, .uv = {0, 0}};
}

// Two triangles covering the NDC rectangle [x0,x1] x [y0,y1] at depth z.
inline Mesh ndc_quad(float x0, float y0, float x1, float y1, float z = 0.5f) {
  Mesh mesh;
  mesh.name = "quad";
  mesh.vertices = {vertex_at(x0, y0, z), vertex_at(x1, y0, z), vertex_at(x1, y1, z), vertex_at(x0, y1, z)};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

// A quad whose edges lie exactly on pixel boundaries: it covers the pixel columns
// [px0, px1) and rows [py0, py1) of a width x height image, row 0 at the top. Edges
// on boundaries never pass through a pixel centre, so the fill rule does not matter.
inline Mesh pixel_rect_quad(int px0, int py0, int px1, int py1, int width, int height, float z = 0.5f) {
  auto ndc_x = [&](int px) { return 2.0f * float(px) / float(width) - 1.0f; };
  auto ndc_y = [&](int py) { return 1.0f - 2.0f * float(py) / float(height); };  // +1 is the top row
  return ndc_quad(ndc_x(px0), ndc_y(py1), ndc_x(px1), ndc_y(py0), z);
}

// Larger than the viewport on every side: covers every pixel.
inline Mesh full_screen_quad(float z = 0.5f) { return ndc_quad(-1.5f, -1.5f, 1.5f, 1.5f, z); }

using test::MapResolver;
using test::MapTextureResolver;

inline size_t covered_pixel_count(const Image& image) {
  size_t n = 0;
  for (uint8_t c : image.coverage) n += c;
  return n;
}

}  // namespace shaderbed::vulkan_test

namespace shaderbed::vulkan_test {

inline Result<RenderOutput> draw(const CompiledProgram& program, const Mesh& mesh, const UniformResolver& uniforms,
                                 int width = 64, int height = 64, ShaderPath path = ShaderPath::spirv) {
  Backend* backend = shared_backend();
  if (backend == nullptr) return fail(ErrorStage::none, "test: no Vulkan backend");
  return backend->render(DrawJob{.program = program, .path = path, .mesh = mesh, .uniforms = uniforms,
                                 .width = width, .height = height});
}

inline Result<RenderOutput> draw_textured(const CompiledProgram& program, const Mesh& mesh,
                                          const UniformResolver& uniforms, const TextureResolver* textures,
                                          int width, int height) {
  Backend* backend = shared_backend();
  if (backend == nullptr) return fail(ErrorStage::none, "test: no Vulkan backend");
  return backend->render(DrawJob{.program = program, .path = ShaderPath::spirv, .mesh = mesh, .uniforms = uniforms,
                                 .width = width, .height = height, .textures = textures});
}

}  // namespace shaderbed::vulkan_test
