// The native-GLSL path: the author's source through Mesa's own compiler, with uniforms
// found by GL introspection (loose uniforms, blocks without layout(binding), instanced
// blocks) and compile errors pointing at the author's line.
#include <string>

#include <gtest/gtest.h>

#include "GlTestSupport.h"

namespace shaderbed::gl_test {
namespace {

constexpr int kNativeWidth = 64;
constexpr int kNativeHeight = 32;

Result<RenderOutput> draw_native(const CompiledProgram& program, const Mesh& mesh, const UniformResolver& uniforms) {
  auto backend = gl_backend();
  if (!backend) return std::unexpected(backend.error());
  return (*backend)->render(DrawJob{.program = program, .path = ShaderPath::native_glsl, .mesh = mesh,
                                    .uniforms = uniforms, .width = kNativeWidth, .height = kNativeHeight});
}

void expect_pixel(const Image& image, int x, int y, float r, float g, float b, float a) {
  const float* p = image.pixel(x, y);
  EXPECT_EQ(p[0], r) << "at (" << x << ", " << y << ")";
  EXPECT_EQ(p[1], g) << "at (" << x << ", " << y << ")";
  EXPECT_EQ(p[2], b) << "at (" << x << ", " << y << ")";
  EXPECT_EQ(p[3], a) << "at (" << x << ", " << y << ")";
}

TEST(GlNativeGlsl, LooseUniformsReachTheShader) {
  const CompiledProgram program = native_glsl_only(R"(#version 450
layout(location = 0) in vec3 position;
uniform mat4 clip_from_object;
void main() { gl_Position = clip_from_object * vec4(position, 1.0); }
)",
                                                   R"(#version 450
uniform vec4 tint;
uniform float weights[3];
uniform int mode;
layout(location = 0) out vec4 colour;
void main() { colour = tint * (weights[0] + weights[1] + weights[2]) * float(mode); }
)");
  const MapResolver uniforms({
      {"clip_from_object", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5f, -0.5f, 0, 1}},
      {"tint", {0.125f, 0.75f, -1.0f, 0.5f}},
      {"weights", {0.5f, 0.5f, 1.0f}},
      {"mode", {1}},
  });
  auto out = draw_native(program, ndc_rectangle(-0.5f, 0.0f, 0.5f, 1.0f), uniforms);
  ASSERT_TRUE(out) << out.error().to_string();
  // Translated by (+0.5, -0.5): columns 32..63, rows 8..23.
  EXPECT_EQ(coverage_count(out->image), 32 * 16);
  EXPECT_TRUE(out->image.covered(32, 8));
  EXPECT_TRUE(out->image.covered(63, 23));
  EXPECT_FALSE(out->image.covered(31, 8));
  expect_pixel(out->image, 40, 10, 0.25f, 1.5f, -2.0f, 1.0f);
}

TEST(GlNativeGlsl, MissingLooseUniformIsAnErrorNamingIt) {
  const CompiledProgram program = native_glsl_only(kPassThroughVertex, R"(#version 450
uniform vec4 tint;
layout(location = 0) out vec4 colour;
void main() { colour = tint; }
)");
  auto out = draw_native(program, ndc_rectangle(-1, -1, 1, 1), MapResolver{});
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().message.find("'tint'"), std::string::npos) << out.error().to_string();
  EXPECT_EQ(out.error().backend, "gl");
}

TEST(GlNativeGlsl, BlocksWithoutBindingGetDistinctBuffers) {
  // Neither block says layout(binding): GL puts both at binding 0, where one buffer
  // would feed both. The backend must give them separate bindings.
  const CompiledProgram program = native_glsl_only(kPassThroughVertex, R"(#version 450
layout(std140) uniform First { vec4 first; };
layout(std140) uniform Second { vec4 second; } second_block;
layout(location = 0) out vec4 colour;
void main() { colour = first + second_block.second; }
)");
  const MapResolver uniforms({{"first", {0.25f, 0, 0, 0}}, {"second", {0, 1.5f, -2.0f, 1.0f}}});
  auto out = draw_native(program, ndc_rectangle(-1, -1, 1, 1), uniforms);
  ASSERT_TRUE(out) << out.error().to_string();
  expect_pixel(out->image, 3, 3, 0.25f, 1.5f, -2.0f, 1.0f);
}

TEST(GlNativeGlsl, RowMajorBlockMatrixIsUploadedTransposed) {
  // layout(row_major): GL stores rows in the registers; the packing must follow
  // GL_IS_ROW_MAJOR or the translation lands in the wrong place.
  const CompiledProgram program = native_glsl_only(R"(#version 450
layout(location = 0) in vec3 position;
layout(binding = 2, std140, row_major) uniform Transform { mat4 clip_from_object; };
void main() { gl_Position = clip_from_object * vec4(position, 1.0); }
)",
                                                   R"(#version 450
layout(location = 0) out vec4 colour;
void main() { colour = vec4(1.0); }
)");
  const MapResolver uniforms({{"clip_from_object", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5f, -0.5f, 0, 1}}});
  auto out = draw_native(program, ndc_rectangle(-0.5f, 0.0f, 0.5f, 1.0f), uniforms);
  ASSERT_TRUE(out) << out.error().to_string();
  EXPECT_EQ(coverage_count(out->image), 32 * 16);
  EXPECT_TRUE(out->image.covered(32, 8));
  EXPECT_TRUE(out->image.covered(63, 23));
}

TEST(GlNativeGlsl, CompileErrorReportsFileAndLine) {
  const CompiledProgram program = native_glsl_only(kPassThroughVertex, R"(#version 450
layout(location = 0) out vec4 colour;

void main() {
  colour = vec4(undeclared_thing);
}
)",
                                                   "ok.vert", "broken.frag");
  auto out = draw_native(program, ndc_rectangle(-1, -1, 1, 1), MapResolver{});
  ASSERT_FALSE(out);
  const Error& e = out.error();
  EXPECT_EQ(e.file, "broken.frag");
  EXPECT_EQ(e.line, 5);
  EXPECT_GT(e.column, 0);
  EXPECT_EQ(e.stage, ErrorStage::gl);
  EXPECT_EQ(e.backend, "gl");
  EXPECT_NE(e.message.find("undeclared_thing"), std::string::npos) << e.to_string();
  EXPECT_NE(e.message.find("glsl path"), std::string::npos) << e.to_string();
}

TEST(GlNativeGlsl, VertexCompileErrorNamesTheVertexFile) {
  const CompiledProgram program = native_glsl_only(R"(#version 450
layout(location = 0) in vec3 position;
void main() { gl_Position = vec4(position, 1.0) }
)",
                                                   R"(#version 450
layout(location = 0) out vec4 colour;
void main() { colour = vec4(1.0); }
)",
                                                   "broken.vert", "ok.frag");
  auto out = draw_native(program, ndc_rectangle(-1, -1, 1, 1), MapResolver{});
  ASSERT_FALSE(out);
  EXPECT_EQ(out.error().file, "broken.vert");
  EXPECT_EQ(out.error().line, 3) << out.error().to_string();
}

TEST(GlNativeGlsl, LinkErrorNamesBothFiles) {
  // The fragment shader reads a varying the vertex shader never writes.
  const CompiledProgram program = native_glsl_only(kPassThroughVertex, R"(#version 450
layout(location = 3) in vec2 never_written;
layout(location = 0) out vec4 colour;
void main() { colour = vec4(never_written, 0.0, 1.0); }
)",
                                                   "a.vert", "b.frag");
  auto out = draw_native(program, ndc_rectangle(-1, -1, 1, 1), MapResolver{});
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().message.find("a.vert"), std::string::npos) << out.error().to_string();
  EXPECT_NE(out.error().message.find("b.frag"), std::string::npos) << out.error().to_string();
  EXPECT_NE(out.error().message.find("link"), std::string::npos) << out.error().to_string();
}

}  // namespace
}  // namespace shaderbed::gl_test
