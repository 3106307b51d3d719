// A DX9 effect pass's render states on OSMesa (llvmpipe), on the SPIR-V and SPIRV-Cross paths (backends/RenderState.h): CullMode culls
// the winding D3D names (CCW, the default, culls the back faces of GLUT's shapes under
// the scene's D3D camera), FillMode WIREFRAME covers fewer pixels, ZEnable and
// ZWriteEnable change the torus, AlphaBlendEnable blends with the cleared target, and
// states that differ are different pipelines.
#include <gtest/gtest.h>

#include "EffectRenderStates.h"
#include "GlTestSupport.h"

namespace shaderbed {
namespace {

using namespace test;

// Both GL paths an HLSL effect takes: glslang's SPIR-V and SPIRV-Cross's GLSL.
Image draw_on(ShaderPath path, const std::string& shape, const std::string& states, const std::string& alpha,
              int size) {
  auto backend = gl_test::gl_backend();
  if (!backend) {
    ADD_FAILURE() << backend.error().to_string();
    return {};
  }
  auto image = draw_with_states(**backend, path, shape, states, alpha, size);
  EXPECT_TRUE(image) << to_string(path) << ": " << image.error().to_string();
  return image ? std::move(*image) : Image{};
}

Image draw(const std::string& shape, const std::string& states, const std::string& alpha = "1.0",
           int size = kStateImageSize) {
  Image spirv = draw_on(ShaderPath::spirv, shape, states, alpha, size);
  const Image cross = draw_on(ShaderPath::cross_glsl, shape, states, alpha, size);
  EXPECT_EQ(differing_pixels(spirv, cross, 1e-5f), 0) << "the SPIR-V and cross-compiled paths disagree: " << states;
  return spirv;
}

TEST(GlRenderState, CullModeCcwCullsOnlyBackFacesAndCwTheFrontOnes) {
  const Image none = draw("sphere", "CullMode = NONE;");
  const Image ccw = draw("sphere", "CullMode = CCW;");
  const Image cw = draw("sphere", "CullMode = CW;");
  ASSERT_GT(covered(none), 300);
  EXPECT_EQ(differing_pixels(none, ccw), 0) << "D3D's default CullMode must only remove hidden faces";
  EXPECT_GT(differing_pixels(none, cw), covered(none) / 2) << "CW culls the visible faces: the inside shows";
}

TEST(GlRenderState, WireframeCoversFewerPixels) {
  // Large enough that the low-tessellation torus's edges are far apart.
  const Image solid = draw("torus", "FillMode = SOLID;", "1.0", 128);
  const Image wire = draw("torus", "FillMode = WIREFRAME;", "1.0", 128);
  ASSERT_GT(covered(solid), 1000);
  EXPECT_GT(covered(wire), 0);
  EXPECT_LT(covered(wire), covered(solid) * 9 / 10) << covered(wire) << " of " << covered(solid);
}

TEST(GlRenderState, ZEnableAndZWriteEnableChangeTheTorus) {
  const Image depth = draw("torus", "CullMode = NONE; ZEnable = TRUE;");
  const Image no_test = draw("torus", "CullMode = NONE; ZEnable = FALSE;");
  const Image no_write = draw("torus", "CullMode = NONE; ZWriteEnable = FALSE;");
  EXPECT_GT(differing_pixels(depth, no_test), 20);
  // One draw into a cleared buffer: without writes every fragment passes, as without the test.
  EXPECT_EQ(differing_pixels(no_test, no_write), 0);
  EXPECT_EQ(covered(depth), covered(no_test)) << "coverage is still read from depth";
}

TEST(GlRenderState, AlphaBlendingMixesWithTheClearedTarget) {
  const Image opaque = draw("sphere", "AlphaBlendEnable = FALSE;", "0.5");
  const Image blended = draw("sphere", "AlphaBlendEnable = TRUE; SrcBlend = SRCALPHA; DestBlend = INVSRCALPHA;", "0.5");
  ASSERT_EQ(covered(opaque), covered(blended));
  int checked = 0;
  for (size_t i = 0; i < opaque.coverage.size(); ++i) {
    if (!opaque.coverage[i]) continue;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(blended.rgba[i * 4 + c], 0.5f * opaque.rgba[i * 4 + c], 1e-5f) << i;
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

TEST(GlRenderState, TheRenderStateIsPartOfThePipelineKey) {
  auto program = compile_state_effect("CullMode = CW;");
  ASSERT_TRUE(program) << program.error().to_string();
  EXPECT_EQ(program->render_state.cull, CullMode::cw);
  EXPECT_NE(program_key(*program, ShaderPath::spirv, program->render_state),
            program_key(*program, ShaderPath::spirv, RenderState{}));
}

TEST(GlRenderState, SamplerStateAddressModesReachTheSampler) {
  auto backend = gl_test::gl_backend();
  ASSERT_TRUE(backend) << backend.error().to_string();
  const std::pair<const char*, std::array<float, 4>> expected[] = {
      {"WRAP", {1, 0, 0, 1}}, {"CLAMP", {0, 1, 0, 1}}, {"MIRROR", {0, 1, 0, 1}}, {"BORDER", {1, 1, 1, 1}}};
  for (ShaderPath path : {ShaderPath::spirv, ShaderPath::cross_glsl}) {
    for (const auto& [mode, rgba] : expected) {
      auto colour = sampled_colour(**backend, path, mode);
      ASSERT_TRUE(colour) << mode << ": " << colour.error().to_string();
      for (int c = 0; c < 4; ++c) EXPECT_EQ((*colour)[c], rgba[c]) << to_string(path) << " AddressU = " << mode << ", channel " << c;
    }
  }
}

}  // namespace
}  // namespace shaderbed
