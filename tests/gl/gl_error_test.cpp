// Bad input is an Error value, never an abort, and a failed render leaves the backend
// able to draw again.
#include <string>

#include <gtest/gtest.h>

#include "GlTestSupport.h"

namespace shaderbed::gl_test {
namespace {

const char* const kWhite = R"(#version 450
layout(location = 0) out vec4 colour;
void main() { colour = vec4(1.0); }
)";

Result<RenderOutput> render_small(const CompiledProgram& program, ShaderPath path, const Mesh& mesh, int width = 16,
                            int height = 16) {
  auto backend = gl_backend();
  if (!backend) return std::unexpected(backend.error());
  const MapResolver none;
  return (*backend)->render(
      DrawJob{.program = program, .path = path, .mesh = mesh, .uniforms = none, .width = width, .height = height});
}

TEST(GlErrors, BackendDescribesItself) {
  auto backend = gl_backend();
  ASSERT_TRUE(backend) << backend.error().to_string();
  EXPECT_EQ((*backend)->name(), "gl");
  EXPECT_NE((*backend)->driver_version().find("Mesa"), std::string::npos) << (*backend)->driver_version();
  EXPECT_EQ((*backend)->paths(Language::glsl).size(), 3u);
  EXPECT_EQ((*backend)->paths(Language::hlsl),
            (std::vector<ShaderPath>{ShaderPath::spirv, ShaderPath::cross_glsl}));
  EXPECT_EQ((*backend)->paths(Language::cg), (*backend)->paths(Language::hlsl));
}

TEST(GlErrors, RejectsEmptyAndHugeTargets) {
  const CompiledProgram program = native_glsl_only(kPassThroughVertex, kWhite);
  for (auto [w, h] : {std::pair{0, 16}, std::pair{16, -1}, std::pair{1 << 20, 16}}) {
    auto out = render_small(program, ShaderPath::native_glsl, ndc_rectangle(-1, -1, 1, 1), w, h);
    ASSERT_FALSE(out) << w << "x" << h;
    EXPECT_EQ(out.error().stage, ErrorStage::gl);
  }
}

TEST(GlErrors, RejectsIndicesPastTheVertices) {
  Mesh mesh = ndc_rectangle(-1, -1, 1, 1);
  mesh.indices.back() = 99;
  auto out = render_small(native_glsl_only(kPassThroughVertex, kWhite), ShaderPath::native_glsl, mesh);
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().message.find("99"), std::string::npos) << out.error().to_string();
}

TEST(GlErrors, RejectsPartialTriangles) {
  Mesh mesh = ndc_rectangle(-1, -1, 1, 1);
  mesh.indices.pop_back();
  EXPECT_FALSE(render_small(native_glsl_only(kPassThroughVertex, kWhite), ShaderPath::native_glsl, mesh));
}

TEST(GlErrors, NoNativePathForHlsl) {
  CompiledProgram program = native_glsl_only(kPassThroughVertex, kWhite);
  program.language = Language::hlsl;
  auto out = render_small(program, ShaderPath::native_glsl, ndc_rectangle(-1, -1, 1, 1));
  ASSERT_FALSE(out);
  EXPECT_EQ(out.error().backend, "gl");
}

TEST(GlErrors, MissingSpirvIsAnError) {
  // native_glsl_only fills no SPIR-V and no cross GLSL.
  const CompiledProgram program = native_glsl_only(kPassThroughVertex, kWhite, "v.vert", "f.frag");
  auto spirv = render_small(program, ShaderPath::spirv, ndc_rectangle(-1, -1, 1, 1));
  ASSERT_FALSE(spirv);
  EXPECT_EQ(spirv.error().file, "v.vert");
  EXPECT_NE(spirv.error().message.find("spirv path"), std::string::npos) << spirv.error().to_string();
  auto cross = render_small(program, ShaderPath::cross_glsl, ndc_rectangle(-1, -1, 1, 1));
  ASSERT_FALSE(cross);
  EXPECT_NE(cross.error().message.find("cross path"), std::string::npos) << cross.error().to_string();
}

TEST(GlErrors, UnknownVertexInputIsNamed) {
  const CompiledProgram program = native_glsl_only(R"(#version 450
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 wobble;
void main() { gl_Position = vec4(position + wobble, 1.0); }
)",
                                                   kWhite);
  auto out = render_small(program, ShaderPath::native_glsl, ndc_rectangle(-1, -1, 1, 1));
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().message.find("wobble"), std::string::npos) << out.error().to_string();
}

TEST(GlErrors, SamplersAreReportedNotIgnored) {
  const CompiledProgram program = native_glsl_only(kPassThroughVertex, R"(#version 450
layout(binding = 0) uniform sampler2D albedo;
layout(location = 0) out vec4 colour;
void main() { colour = texture(albedo, vec2(0.5)); }
)");
  auto out = render_small(program, ShaderPath::native_glsl, ndc_rectangle(-1, -1, 1, 1));
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().message.find("albedo"), std::string::npos) << out.error().to_string();
}

TEST(GlErrors, DrawsAgainAfterAFailure) {
  const CompiledProgram broken = native_glsl_only(kPassThroughVertex, "#version 450\nvoid main() { nope; }\n");
  ASSERT_FALSE(render_small(broken, ShaderPath::native_glsl, ndc_rectangle(-1, -1, 1, 1)));
  auto out = render_small(native_glsl_only(kPassThroughVertex, kWhite), ShaderPath::native_glsl,
                    ndc_rectangle(-1, -1, 1, 1), 8, 4);
  ASSERT_TRUE(out) << out.error().to_string();
  EXPECT_EQ(coverage_count(out->image), 8 * 4);
  EXPECT_EQ(out->image.pixel(7, 3)[0], 1.0f);
}

}  // namespace
}  // namespace shaderbed::gl_test
