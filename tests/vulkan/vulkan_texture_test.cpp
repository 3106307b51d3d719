// Lookup textures on lavapipe: R32F texels reach the shader unchanged at texel centres,
// linear filtering averages neighbours, clamp-to-edge holds outside [0, 1], in 1D, 2D
// and 3D, from GLSL and from DX9-style HLSL (sampler2D + tex2D); every way a texture
// can fail to fit its sampler is an Error naming the sampler and the backend. One test
// measures the driver's filtering error against exact linear interpolation. The GL test
// runs the same checks (TextureProbes.h).
#include <string>

#include "TextureProbes.h"
#include "VulkanTestSupport.h"

namespace shaderbed::vulkan_test {
namespace {

using namespace texture_probes;

// lavapipe through glslang's Vulkan SPIR-V.
const TextureBench kLavapipe{
    .compile_fragment = [](const std::string& fragment) { return compile_glsl(passthrough_vertex_shader, fragment); },
    .draw =
        [](const CompiledProgram& program, const UniformResolver& uniforms, const TextureResolver* textures, int width,
           int height) { return draw_textured(program, full_screen_quad(), uniforms, textures, width, height); },
    .backend = "vulkan"};

TEST(VulkanTexture, TexelCentresReturnTexelsExactly2D) { expect_texel_centres_exact_2d(kLavapipe); }
TEST(VulkanTexture, HalfwayBetweenTexelCentresIsTheMean2D) { expect_halfway_is_the_mean_2d(kLavapipe); }
TEST(VulkanTexture, OutsideTheUnitSquareClampsToTheEdgeTexel2D) { expect_clamp_to_edge_2d(kLavapipe); }
TEST(VulkanTexture, ThreeDimensionalTextureFiltersTrilinearly) { expect_trilinear_3d(kLavapipe); }
TEST(VulkanTexture, OneDimensionalTextureFiltersLinearly) { expect_linear_1d(kLavapipe); }

TEST(VulkanTexture, HlslDx9Sampler2DWithTex2D) {
  auto program = compile_dx9_probe();
  ASSERT_TRUE(program) << program.error().to_string();
  ASSERT_EQ(program->fragment.reflection.samplers.size(), 1u);
  EXPECT_EQ(program->fragment.reflection.samplers[0].name, "Lut");
  expect_dx9_tex2d_filters(kLavapipe, *program);
}

// A texture per sampler, in both stages: each sampler reads its own texture, and the
// vertex stage samples too.
TEST(VulkanTexture, EverySamplerOfBothStagesGetsItsTexture) {
  auto program = compile_glsl(R"(#version 450
layout(location = 0) in vec3 position;
layout(set = 1, binding = 0) uniform sampler1D ramp;
layout(location = 0) out float from_vertex;
void main() { from_vertex = textureLod(ramp, 0.75, 0.0).r; gl_Position = vec4(position, 1.0); }
)",
                              R"(#version 450
layout(set = 0, binding = 1) uniform sampler2D first;
layout(set = 0, binding = 3) uniform sampler2D second;
layout(location = 0) in float from_vertex;
layout(location = 0) out vec4 colour;
void main() { colour = vec4(texture(first, vec2(0.75, 0.25)).r, texture(second, vec2(0.25, 0.75)).r, from_vertex, 1.0); }
)");
  ASSERT_TRUE(program) << program.error().to_string();
  const MapTextureResolver textures({
      {"ramp", make_texture("ramp", 1, 2, 1, 1, {0.25f, 0.5f})},
      {"first", make_texture("first", 2, 2, 2, 1, {1.0f, 2.0f, 3.0f, 4.0f})},
      {"second", make_texture("second", 2, 2, 2, 1, {-1.0f, -2.0f, -3.0f, -4.0f})},
  });
  const MapResolver no_uniforms;
  auto out = draw_textured(*program, full_screen_quad(), no_uniforms, &textures, 4, 4);
  ASSERT_TRUE(out) << out.error().to_string();
  const float* p = out->image.pixel(2, 2);
  EXPECT_EQ(p[0], 2.0f);
  EXPECT_EQ(p[1], -3.0f);
  EXPECT_EQ(p[2], 0.5f);
}

// A resolver that hands one texture to every sampler: uploaded once, read by both.
class OneTextureForAll final : public TextureResolver {
 public:
  explicit OneTextureForAll(Texture texture) : texture_(std::move(texture)) {}
  Result<const Texture*> texture(const SamplerBinding&) const override { return &texture_; }

 private:
  Texture texture_;
};

TEST(VulkanTexture, OneTextureBoundToTwoSamplers) {
  auto program = compile_glsl(passthrough_vertex_shader, R"(#version 450
layout(set = 0, binding = 0) uniform sampler2D first;
layout(set = 2, binding = 5) uniform sampler2D second;
layout(location = 0) out vec4 colour;
void main() { colour = vec4(texture(first, vec2(0.25, 0.25)).r, texture(second, vec2(0.75, 0.75)).r, 0.0, 1.0); }
)");
  ASSERT_TRUE(program) << program.error().to_string();
  const OneTextureForAll textures(make_texture("shared", 2, 2, 2, 1, {1.0f, 2.0f, 3.0f, 4.0f}));
  const MapResolver no_uniforms;
  auto out = draw_textured(*program, full_screen_quad(), no_uniforms, &textures, 4, 4);
  ASSERT_TRUE(out) << out.error().to_string();
  EXPECT_EQ(out->image.pixel(1, 1)[0], 1.0f);
  EXPECT_EQ(out->image.pixel(1, 1)[1], 4.0f);
}

TEST(VulkanTexture, MissingTextureIsAnErrorNamingTheSampler) { expect_missing_texture_error(kLavapipe); }
TEST(VulkanTexture, NoResolverIsAnErrorNamingTheSampler) { expect_no_resolver_error(kLavapipe); }
TEST(VulkanTexture, DimensionMismatchIsAnError) { expect_dimension_mismatch_error(kLavapipe); }
TEST(VulkanTexture, TexelCountMismatchIsAnError) { expect_texel_count_error(kLavapipe); }

TEST(VulkanTexture, UnusedExtentsMustBeOne) {
  const MapTextureResolver textures({{"lut", make_texture("flat", 2, 2, 2, 2, std::vector<float>(8, 0.5f))}});
  auto out = draw_probe_program(kLavapipe, &textures);
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().message.find("unused extents must be 1"), std::string::npos) << out.error().to_string();
}

TEST(VulkanTexture, SamplerAndUniformBlockOnOneBindingIsAnError) {
  auto program = compile_glsl(passthrough_vertex_shader, R"(#version 450
layout(set = 0, binding = 0) uniform Material { vec4 tint; };
layout(set = 0, binding = 0) uniform sampler2D lut;
layout(location = 0) out vec4 colour;
void main() { colour = texture(lut, tint.xy); }
)");
  ASSERT_TRUE(program) << program.error().to_string();
  const MapTextureResolver textures({{"lut", kTexture2D}});
  const MapResolver uniforms({{"tint", {0.5f, 0.5f, 0, 0}}});
  auto out = draw_textured(*program, full_screen_quad(), uniforms, &textures, 4, 4);
  ASSERT_FALSE(out);
  const std::string text = out.error().to_string();
  EXPECT_NE(text.find("'lut'"), std::string::npos) << text;
  EXPECT_NE(text.find("'Material'"), std::string::npos) << text;
}

TEST(VulkanTexture, FilteringErrorAgainstExactLinearInterpolation) {
  expect_filtering_close_to_exact(kLavapipe, "lavapipe");
}

}  // namespace
}  // namespace shaderbed::vulkan_test
