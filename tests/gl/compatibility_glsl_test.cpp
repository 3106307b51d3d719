// GL-era GLSL on the GL backend: the author's source compiled by Mesa in a
// compatibility-profile context, with the fixed-function state set from the same
// values the SPIR-V paths upload as the dialect's uniforms (GlFixedFunctionState.h),
// so every path draws the same pixels; and Vulkan GLSL skipped on the native path.
#include <string>

#include <gtest/gtest.h>

#include "GlTestSupport.h"
#include "compile/Compiler.h"

namespace shaderbed::gl_test {
namespace {

constexpr int kSize = 32;

Result<CompiledProgram> compile_legacy(const std::string& vertex, const std::string& fragment) {
  return compile_program(ProgramSource{.language = Language::glsl,
                                       .vertex = {.stage = Stage::vertex, .path = "legacy.vert", .text = vertex},
                                       .fragment = {.stage = Stage::fragment, .path = "legacy.frag", .text = fragment}});
}

Result<RenderOutput> draw_compatibility(const CompiledProgram& program, ShaderPath path, const Mesh& mesh,
                          const UniformResolver& uniforms) {
  auto backend = gl_backend();
  if (!backend) return std::unexpected(backend.error());
  return (*backend)->render(DrawJob{.program = program, .path = path, .mesh = mesh, .uniforms = uniforms,
                                    .width = kSize, .height = kSize});
}

const std::vector<float> kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
const std::vector<float> kMoveBackALittle = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0.25f, 1};

class CompatibilityGlsl : public ::testing::TestWithParam<ShaderPath> {};

// Light and material through the light product, the light position as bound (view space,
// not moved by the modelview), and the matrices through ftransform().
TEST_P(CompatibilityGlsl, FixedFunctionStateReachesTheShaderAsTheCaseBindsIt) {
  auto program = compile_legacy(
      "varying vec4 product;\n"
      "varying vec4 light;\n"
      "void main() {\n"
      "  product = gl_FrontLightProduct[0].diffuse;\n"
      "  light = gl_LightSource[0].position;\n"
      "  gl_Position = ftransform();\n"
      "}\n",
      "varying vec4 product;\n"
      "varying vec4 light;\n"
      "void main() { gl_FragColor = product * gl_FrontMaterial.shininess + light.w * (light - vec4(1.0, 2.0, 3.0, 1.0)); }\n");
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver uniforms({
      {"gl_ModelViewMatrix", kMoveBackALittle},
      {"gl_ProjectionMatrix", kIdentity},
      {"gl_ModelViewProjectionMatrix", kMoveBackALittle},
      {"gl_LightSource[0].diffuse", {0.5f, 0.25f, 1.0f, 1.0f}},
      {"gl_LightSource[0].position", {1.0f, 2.0f, 3.0f, 1.0f}},
      {"gl_FrontMaterial.diffuse", {0.5f, 0.5f, 0.5f, 0.75f}},
      {"gl_FrontMaterial.shininess", {2.0f}},
  });
  auto out = draw_compatibility(*program, GetParam(), ndc_rectangle(-1, -1, 1, 1, 0.25f), uniforms);
  ASSERT_TRUE(out) << out.error().to_string();
  EXPECT_EQ(coverage_count(out->image), kSize * kSize);
  const float* p = out->image.pixel(kSize / 2, kSize / 2);
  // rgb: light * material; alpha: the material's (as Mesa's light products); doubled.
  EXPECT_FLOAT_EQ(p[0], 0.5f);
  EXPECT_FLOAT_EQ(p[1], 0.25f);
  EXPECT_FLOAT_EQ(p[2], 1.0f);
  EXPECT_FLOAT_EQ(p[3], 1.5f);
}

TEST_P(CompatibilityGlsl, UnboundLightStateIsAnErrorNamingTheLegacyUniform) {
  auto program = compile_legacy("void main() { gl_Position = ftransform(); }\n",
                                "void main() { gl_FragColor = gl_LightSource[0].specular; }\n");
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver uniforms({{"gl_ModelViewMatrix", kIdentity}, {"gl_ProjectionMatrix", kIdentity},
                              {"gl_ModelViewProjectionMatrix", kIdentity}});
  auto out = draw_compatibility(*program, GetParam(), ndc_rectangle(-1, -1, 1, 1), uniforms);
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().message.find("gl_LightSource[0].specular"), std::string::npos) << out.error().message;
}

INSTANTIATE_TEST_SUITE_P(EveryPath, CompatibilityGlsl,
                         ::testing::Values(ShaderPath::native_glsl, ShaderPath::spirv, ShaderPath::cross_glsl));

TEST(VulkanGlslOnGl, TheNativePathIsSkippedWithTheReasonAndTheSpirvPathDraws) {
  auto program = compile_legacy(
      "#version 450\n"
      "layout(location = 0) in vec3 position;\n"
      "void main() { gl_Position = vec4(position, 1.0); }\n",
      "#version 450\n"
      "layout(set = 0, binding = 0) uniform Colour { vec4 colour; };\n"
      "layout(location = 0) out vec4 result;\n"
      "void main() { result = colour; }\n");
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver uniforms({{"colour", {0.25f, 0.5f, 0.75f, 1.0f}}});
  auto native = draw_compatibility(*program, ShaderPath::native_glsl, ndc_rectangle(-1, -1, 1, 1), uniforms);
  ASSERT_FALSE(native);
  EXPECT_TRUE(native.error().skipped) << native.error().to_string();
  EXPECT_NE(native.error().message.find("layout(set) at line 2"), std::string::npos) << native.error().message;
  auto spirv = draw_compatibility(*program, ShaderPath::spirv, ndc_rectangle(-1, -1, 1, 1), uniforms);
  ASSERT_TRUE(spirv) << spirv.error().to_string();
  EXPECT_FLOAT_EQ(spirv->image.pixel(4, 4)[1], 0.5f);
}

// Push constants exist only for Vulkan: the program still compiles (for the Vulkan
// backend), and every GL path is a skipped cell saying why.
TEST(VulkanGlslOnGl, PushConstantsSkipEveryGlPath) {
  auto program = compile_legacy(
      "#version 450\n"
      "layout(location = 0) in vec3 position;\n"
      "void main() { gl_Position = vec4(position, 1.0); }\n",
      "#version 450\n"
      "layout(push_constant) uniform Colour { vec4 colour; } pc;\n"
      "layout(location = 0) out vec4 result;\n"
      "void main() { result = pc.colour; }\n");
  ASSERT_TRUE(program) << program.error().to_string();
  EXPECT_FALSE(program->fragment.spirv.empty());
  const MapResolver uniforms({{"colour", {0.25f, 0.5f, 0.75f, 1.0f}}});
  for (ShaderPath path : {ShaderPath::native_glsl, ShaderPath::spirv, ShaderPath::cross_glsl}) {
    auto out = draw_compatibility(*program, path, ndc_rectangle(-1, -1, 1, 1), uniforms);
    ASSERT_FALSE(out) << to_string(path);
    EXPECT_TRUE(out.error().skipped) << out.error().to_string();
    EXPECT_NE(out.error().message.find("push_constant"), std::string::npos) << out.error().message;
  }
}

}  // namespace
}  // namespace shaderbed::gl_test
