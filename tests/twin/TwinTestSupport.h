#pragma once
// What the twin's execution tests share: GLSL compiled to Vulkan SPIR-V by the project's
// compile stage, a twin program loaded from it, uniform bytes written at std140 offsets,
// and a draw of a full-screen quad (or any mesh) with the twin.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <expected>
#include <span>
#include <string>
#include <vector>

#include "compile/Compiler.h"
#include "compile/SpirvTools.h"
#include "twin/TwinDraw.h"

namespace twin_tests {

// Vulkan-target SPIR-V of one GLSL stage, or the compile stage's error.
inline std::expected<std::vector<uint32_t>, std::string> glsl_spirv(shaderbed::Stage stage, const std::string& text) {
  const shaderbed::ShaderSource source{.stage = stage,
                                       .path = stage == shaderbed::Stage::vertex ? "test.vert" : "test.frag",
                                       .text = text};
  auto compiled = shaderbed::compile_stage(shaderbed::Language::glsl, source, shaderbed::Target::vulkan, nullptr);
  if (!compiled) return std::unexpected(compiled.error().to_string());
  return std::move(compiled->spirv);
}

// spirv-opt -O: SSA form with phis, merged and restructured blocks (what the compile stage
// gives HLSL, and what a driver's front end sees after its own passes).
inline std::expected<std::vector<uint32_t>, std::string> optimised(const std::vector<uint32_t>& spirv) {
  auto out = shaderbed::optimize_spirv(spirv, shaderbed::Target::vulkan, shaderbed::OptimizeLevel::performance);
  if (!out) return std::unexpected(out.error().to_string());
  return std::move(*out);
}

enum class Optimise { no, yes };

// Both stages compiled (and optimised, when asked) and loaded into the twin.
inline std::expected<twin::Program, std::string> glsl_program(const std::string& vertex, const std::string& fragment,
                                                              Optimise optimise = Optimise::no) {
  auto vs = glsl_spirv(shaderbed::Stage::vertex, vertex);
  if (!vs) return std::unexpected("vertex: " + vs.error());
  auto fs = glsl_spirv(shaderbed::Stage::fragment, fragment);
  if (!fs) return std::unexpected("fragment: " + fs.error());
  if (optimise == Optimise::yes) {
    vs = optimised(*vs);
    if (!vs) return std::unexpected("spirv-opt, vertex: " + vs.error());
    fs = optimised(*fs);
    if (!fs) return std::unexpected("spirv-opt, fragment: " + fs.error());
  }
  auto program = twin::load_program(*vs, "main", *fs, "main");
  if (!program) return std::unexpected(program.error().to_string());
  return std::move(*program);
}

// Clip position from location 0, as given.
inline constexpr const char* pass_through_vertex = R"(#version 450
layout(location = 0) in vec4 position;
void main() { gl_Position = position; }
)";

// Triangles by vertex streams (location -> 4 values per vertex) and a triangle list.
struct Mesh {
  std::vector<twin::VertexStream> streams;
  uint32_t vertex_count = 0;
  std::vector<uint32_t> indices;
};

// Two triangles covering clip space at depth 0.5, positions at location 0.
inline Mesh full_screen_quad() {
  return Mesh{.streams = {{.location = 0,
                           .values = {-1, -1, 0.5, 1, 1, -1, 0.5, 1, 1, 1, 0.5, 1, -1, 1, 0.5, 1}}},
              .vertex_count = 4,
              .indices = {0, 1, 2, 0, 2, 3}};
}

struct DrawOptions {
  twin::Precision precision = twin::Precision::exact;
  twin::Cull cull = twin::Cull::none;
  unsigned threads = 0;
};

inline twin::TwinResult<twin::TwinImage> draw_mesh(const twin::Program& program, const Mesh& mesh,
                                                   const twin::BoundResources& resources, int width, int height,
                                                   const DrawOptions& options = {}) {
  return twin::draw(twin::DrawInput{.program = program,
                                    .resources = resources,
                                    .streams = mesh.streams,
                                    .vertex_count = mesh.vertex_count,
                                    .indices = mesh.indices,
                                    .width = width,
                                    .height = height,
                                    .precision = options.precision,
                                    .cull = options.cull,
                                    .threads = options.threads});
}

inline twin::TwinResult<twin::TwinImage> draw_quad(const twin::Program& program, const twin::BoundResources& resources,
                                                   int width, int height, const DrawOptions& options = {}) {
  return draw_mesh(program, full_screen_quad(), resources, width, height, options);
}

inline std::array<double, 4> rgba_at(const twin::TwinImage& image, int x, int y) {
  const size_t at = (size_t(y) * size_t(image.width) + size_t(x)) * 4;
  return {image.rgba[at], image.rgba[at + 1], image.rgba[at + 2], image.rgba[at + 3]};
}

inline bool covered(const twin::TwinImage& image, int x, int y) {
  return image.coverage[size_t(y) * size_t(image.width) + size_t(x)] != 0;
}

// A uniform block's bytes, written value by value at the offsets the test computes.
class BlockBytes {
 public:
  explicit BlockBytes(size_t size) : bytes_(size) {}
  void put_float(size_t offset, float value) { put(offset, std::bit_cast<uint32_t>(value)); }
  void put(size_t offset, uint32_t bits) { std::memcpy(bytes_.data() + offset, &bits, 4); }
  std::span<const std::byte> bytes() const { return bytes_; }

 private:
  std::vector<std::byte> bytes_;
};

}  // namespace twin_tests
