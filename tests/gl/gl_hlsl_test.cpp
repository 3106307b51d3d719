// HLSL reaches GL only as SPIR-V or as SPIRV-Cross GLSL. Both paths must honour the
// compile stage's reflection: per-stage $Global blocks that do not collide, and HLSL
// matrices whose registers hold columns (mul(M, v) with M uploaded as D3D did).
#include <string>

#include <gtest/gtest.h>

#include "GlTestSupport.h"
#include "compile/Compiler.h"

namespace shaderbed::gl_test {
namespace {

const char* const kVertex = R"(
float4x4 Transform;
struct VsOut { float4 position : SV_Position; };
VsOut main(float3 position : POSITION) {
  VsOut o;
  o.position = mul(Transform, float4(position, 1.0));
  return o;
}
)";

const char* const kPixel = R"(
float4 Tint;
float Scale;
float4 main() : SV_Target { return Tint * Scale; }
)";

class GlHlsl : public ::testing::TestWithParam<ShaderPath> {};

TEST_P(GlHlsl, GlobalsAndMatricesMatchTheGlslConvention) {
  ProgramSource source;
  source.language = Language::hlsl;
  source.vertex = ShaderSource{.stage = Stage::vertex, .path = "test_vs.hlsl", .text = kVertex, .entry_point = "main"};
  source.fragment = ShaderSource{.stage = Stage::fragment, .path = "test_ps.hlsl", .text = kPixel, .entry_point = "main"};
  auto program = compile_program(source);
  ASSERT_TRUE(program) << program.error().to_string();

  auto backend = gl_backend();
  ASSERT_TRUE(backend) << backend.error().to_string();
  const Mesh mesh = ndc_rectangle(-0.5f, 0.0f, 0.5f, 1.0f);
  const MapResolver uniforms({
      {"Transform", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5f, -0.5f, 0, 1}},  // column-major M
      {"Tint", {0.5f, 3.0f, -4.0f, 2.0f}},
      {"Scale", {0.5f}},
  });
  auto out = (*backend)->render(
      DrawJob{.program = *program, .path = GetParam(), .mesh = mesh, .uniforms = uniforms, .width = 64, .height = 32});
  ASSERT_TRUE(out) << out.error().to_string();
  // Same picture as the GLSL UniformBlocksReachBothStages test: columns 32..63, rows 8..23.
  EXPECT_EQ(coverage_count(out->image), 32 * 16);
  EXPECT_TRUE(out->image.covered(32, 8));
  EXPECT_TRUE(out->image.covered(63, 23));
  const float* p = out->image.pixel(40, 10);
  EXPECT_EQ(p[0], 0.25f);
  EXPECT_EQ(p[1], 1.5f);
  EXPECT_EQ(p[2], -2.0f);
  EXPECT_EQ(p[3], 1.0f);
}

INSTANTIATE_TEST_SUITE_P(SpirvAndCross, GlHlsl, ::testing::Values(ShaderPath::spirv, ShaderPath::cross_glsl),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace shaderbed::gl_test
