// A DX9 effect pass's render states on lavapipe (backends/RenderState.h), by the checks the
// GL test runs too (EffectRenderStates.h): CullMode culls the winding D3D names, FillMode
// WIREFRAME covers fewer pixels, ZEnable and ZWriteEnable change the torus,
// AlphaBlendEnable blends with the cleared target, sampler_state address modes reach the
// sampler, and states that differ are different pipelines.
#include <gtest/gtest.h>

#include "EffectRenderStates.h"
#include "VulkanTestSupport.h"

namespace shaderbed {
namespace {

using namespace test;

Image draw(const std::string& shape, const std::string& states, const std::string& alpha, int size) {
  Backend* backend = vulkan_test::shared_backend();
  if (!backend) return {};
  auto image = draw_with_states(*backend, ShaderPath::spirv, shape, states, alpha, size);
  EXPECT_TRUE(image) << image.error().to_string();
  return image ? std::move(*image) : Image{};
}

TEST(VulkanRenderState, CullModeCcwCullsOnlyBackFacesAndCwTheFrontOnes) { expect_cull_modes(draw); }
TEST(VulkanRenderState, WireframeCoversFewerPixels) { expect_wireframe_covers_fewer_pixels(draw); }
TEST(VulkanRenderState, ZEnableAndZWriteEnableChangeTheTorus) { expect_depth_states_change_the_torus(draw); }
TEST(VulkanRenderState, AlphaBlendingMixesWithTheClearedTarget) { expect_alpha_blending_with_the_cleared_target(draw); }

// Backend-independent; the GL renderer keys its programs by the same program_key.
TEST(VulkanRenderState, TheRenderStateIsPartOfThePipelineKey) {
  auto program = compile_state_effect("CullMode = CW;");
  ASSERT_TRUE(program) << program.error().to_string();
  EXPECT_EQ(program->render_state.cull, CullMode::cw);
  EXPECT_NE(program_key(*program, ShaderPath::spirv, program->render_state),
            program_key(*program, ShaderPath::spirv, RenderState{}));
}

TEST(VulkanRenderState, SamplerStateAddressModesReachTheSampler) {
  Backend* backend = vulkan_test::shared_backend();
  ASSERT_NE(backend, nullptr);
  expect_sampler_address_modes(*backend, {ShaderPath::spirv});
}

}  // namespace
}  // namespace shaderbed
