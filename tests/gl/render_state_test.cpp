// A DX9 effect pass's render states on OSMesa (llvmpipe), on the SPIR-V and SPIRV-Cross
// paths (backends/RenderState.h), by the checks the Vulkan test runs too
// (EffectRenderStates.h): CullMode, FillMode, ZEnable and ZWriteEnable, AlphaBlendEnable,
// and sampler_state address modes; the two paths must draw the same image.
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

Image draw(const std::string& shape, const std::string& states, const std::string& alpha, int size) {
  Image spirv = draw_on(ShaderPath::spirv, shape, states, alpha, size);
  const Image cross = draw_on(ShaderPath::cross_glsl, shape, states, alpha, size);
  EXPECT_EQ(differing_pixels(spirv, cross, 1e-5f), 0) << "the SPIR-V and cross-compiled paths disagree: " << states;
  return spirv;
}

TEST(GlRenderState, CullModeCcwCullsOnlyBackFacesAndCwTheFrontOnes) { expect_cull_modes(draw); }
TEST(GlRenderState, WireframeCoversFewerPixels) { expect_wireframe_covers_fewer_pixels(draw); }
TEST(GlRenderState, ZEnableAndZWriteEnableChangeTheTorus) { expect_depth_states_change_the_torus(draw); }
TEST(GlRenderState, AlphaBlendingMixesWithTheClearedTarget) { expect_alpha_blending_with_the_cleared_target(draw); }

TEST(GlRenderState, SamplerStateAddressModesReachTheSampler) {
  auto backend = gl_test::gl_backend();
  ASSERT_TRUE(backend) << backend.error().to_string();
  expect_sampler_address_modes(**backend, {ShaderPath::spirv, ShaderPath::cross_glsl});
}

}  // namespace
}  // namespace shaderbed
