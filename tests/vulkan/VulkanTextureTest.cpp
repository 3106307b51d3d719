// Lookup textures on lavapipe: R32F texels reach the shader unchanged at texel centres,
// linear filtering averages neighbours, clamp-to-edge holds outside [0, 1], in 1D, 2D
// and 3D, from GLSL and from DX9-style HLSL (sampler2D + tex2D); every way a texture
// can fail to fit its sampler is an Error naming the sampler. One test measures the
// driver's filtering error against exact linear interpolation.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "TextureProbes.h"
#include "VulkanTestSupport.h"

namespace shaderbed::vulkan_test {
namespace {

using namespace texture_probes;

struct UvProbe {
  float u, v = 0.5f, w = 0.5f;
};

// The sampled value at each probe, from one draw of `program` (which reads the
// coordinates from the member `coords_member` of a vec4 array).
Result<std::vector<float>> sample(const CompiledProgram& program, const TextureResolver& textures,
                                  const std::vector<UvProbe>& probes, const std::string& coords_member = "coords") {
  if (probes.size() > size_t(kMaxProbes)) return fail("test", "too many probes");
  std::vector<float> coords(size_t(kMaxProbes) * 4, 0.0f);
  for (size_t p = 0; p < probes.size(); ++p) {
    coords[p * 4 + 0] = probes[p].u;
    coords[p * 4 + 1] = probes[p].v;
    coords[p * 4 + 2] = probes[p].w;
  }
  const MapResolver uniforms({{coords_member, coords}});
  auto out = draw_textured(program, full_screen_quad(), uniforms, &textures, int(probes.size()), 1);
  if (!out) return std::unexpected(out.error());
  std::vector<float> values;
  for (int x = 0; x < int(probes.size()); ++x) values.push_back(out->image.pixel(x, 0)[0]);
  return values;
}

Result<std::vector<float>> sample_glsl(const Texture& texture, const std::vector<UvProbe>& probes) {
  auto program = compile_glsl(passthrough_vertex_shader, probe_fragment_shader(texture.dimensions));
  if (!program) return std::unexpected(program.error());
  const MapTextureResolver textures({{"lut", texture}});
  return sample(*program, textures, probes);
}

// 4 x 2, values chosen so that no mean is a short binary fraction.
const Texture kTexture2D = make_texture("lut2d", 2, 4, 2, 1, {0.1f, 0.7f, 0.35f, 0.9f,     // row 0
                                                              0.45f, 0.2f, 0.65f, 0.05f}); // row 1

TEST(VulkanTexture, TexelCentresReturnTexelsExactly2D) {
  std::vector<UvProbe> probes;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) probes.push_back({(i + 0.5f) / 4, (j + 0.5f) / 2});
  auto values = sample_glsl(kTexture2D, probes);
  ASSERT_TRUE(values) << values.error().to_string();
  for (size_t p = 0; p < probes.size(); ++p) EXPECT_EQ((*values)[p], kTexture2D.texels[p]) << "texel " << p;
}

TEST(VulkanTexture, HalfwayBetweenTexelCentresIsTheMean2D) {
  const Texture& t = kTexture2D;
  const std::vector<UvProbe> probes = {
      {0.25f, 0.25f},  // between (0,0) and (1,0)
      {0.75f, 0.75f},  // between (2,1) and (3,1)
      {0.125f, 0.5f},  // between (0,0) and (0,1)
      {0.5f, 0.5f},    // centre of (1,0) (2,0) (1,1) (2,1)
  };
  const std::vector<double> expected = {
      (texel(t, 0, 0) + texel(t, 1, 0)) / 2.0,
      (texel(t, 2, 1) + texel(t, 3, 1)) / 2.0,
      (texel(t, 0, 0) + texel(t, 0, 1)) / 2.0,
      (texel(t, 1, 0) + texel(t, 2, 0) + texel(t, 1, 1) + texel(t, 2, 1)) / 4.0,
  };
  auto values = sample_glsl(t, probes);
  ASSERT_TRUE(values) << values.error().to_string();
  for (size_t p = 0; p < probes.size(); ++p) EXPECT_NEAR((*values)[p], expected[p], 1e-6) << "probe " << p;
}

TEST(VulkanTexture, OutsideTheUnitSquareClampsToTheEdgeTexel2D) {
  const Texture& t = kTexture2D;
  const std::vector<UvProbe> probes = {{-0.5f, -0.5f}, {1.5f, 0.25f}, {0.375f, 2.0f}, {-3.0f, 5.0f}, {7.0f, -7.0f}};
  const std::vector<float> expected = {texel(t, 0, 0), texel(t, 3, 0), texel(t, 1, 1), texel(t, 0, 1), texel(t, 3, 0)};
  auto values = sample_glsl(t, probes);
  ASSERT_TRUE(values) << values.error().to_string();
  for (size_t p = 0; p < probes.size(); ++p) EXPECT_EQ((*values)[p], expected[p]) << "probe " << p;
}

TEST(VulkanTexture, ThreeDimensionalTextureFiltersTrilinearly) {
  const Texture t = make_texture("lut3d", 3, 4, 2, 2,
                                 {0.1f, 0.7f, 0.35f, 0.9f, 0.45f, 0.2f, 0.65f, 0.05f,     // z = 0
                                  0.55f, 0.15f, 0.8f, 0.3f, 0.95f, 0.6f, 0.25f, 0.4f});  // z = 1
  double cell_mean = 0;  // texels i 1..2, j 0..1, k 0..1
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 1; i < 3; ++i) cell_mean += texel(t, i, j, k) / 8.0;
  const std::vector<UvProbe> probes = {
      {0.125f, 0.25f, 0.25f},  // texel (0,0,0)
      {0.625f, 0.75f, 0.75f},  // texel (2,1,1)
      {0.875f, 0.25f, 0.75f},  // texel (3,0,1)
      {0.5f, 0.5f, 0.5f},      // the cell between 8 texel centres
      {-1.0f, 2.0f, 9.0f},     // clamped to texel (0,1,1)
  };
  auto values = sample_glsl(t, probes);
  ASSERT_TRUE(values) << values.error().to_string();
  EXPECT_EQ((*values)[0], texel(t, 0, 0, 0));
  EXPECT_EQ((*values)[1], texel(t, 2, 1, 1));
  EXPECT_EQ((*values)[2], texel(t, 3, 0, 1));
  EXPECT_NEAR((*values)[3], cell_mean, 1e-6);
  EXPECT_EQ((*values)[4], texel(t, 0, 1, 1));
}

TEST(VulkanTexture, OneDimensionalTextureFiltersLinearly) {
  const Texture t = make_texture("ramp", 1, 8, 1, 1, {0.1f, 0.7f, 0.35f, 0.9f, 0.45f, 0.2f, 0.65f, 0.05f});
  const std::vector<UvProbe> probes = {{0.0625f}, {0.5625f}, {0.25f}, {0.875f}, {-2.0f}, {3.0f}};
  auto values = sample_glsl(t, probes);
  ASSERT_TRUE(values) << values.error().to_string();
  EXPECT_EQ((*values)[0], texel(t, 0));
  EXPECT_EQ((*values)[1], texel(t, 4));
  EXPECT_NEAR((*values)[2], (texel(t, 1) + texel(t, 2)) / 2.0, 1e-6);
  EXPECT_NEAR((*values)[3], (texel(t, 6) + texel(t, 7)) / 2.0, 1e-6);
  EXPECT_EQ((*values)[4], texel(t, 0));
  EXPECT_EQ((*values)[5], texel(t, 7));
}

TEST(VulkanTexture, HlslDx9Sampler2DWithTex2D) {
  ProgramSource source;
  source.language = Language::hlsl;
  source.vertex = ShaderSource{.stage = Stage::vertex, .path = "lut_vs.hlsl", .text = R"(
float4 main(float3 position : POSITION) : POSITION { return float4(position, 1.0); }
)"};
  source.fragment = ShaderSource{.stage = Stage::fragment, .path = "lut_ps.hlsl", .text = R"(
sampler2D Lut : register(s0);
float4 Probes[16];
float4 main(float4 pixel : SV_Position) : COLOR {
  return float4(tex2D(Lut, Probes[(int)pixel.x].xy).r, 0.0, 0.0, 1.0);
}
)"};
  auto program = compile_program(source);
  ASSERT_TRUE(program) << program.error().to_string();
  ASSERT_EQ(program->fragment.reflection.samplers.size(), 1u);
  EXPECT_EQ(program->fragment.reflection.samplers[0].name, "Lut");
  const Texture& t = kTexture2D;
  const MapTextureResolver textures({{"Lut", t}});
  auto values = sample(*program, textures, {{0.125f, 0.25f}, {0.875f, 0.75f}, {0.25f, 0.25f}, {-1.0f, 1.5f}},
                       "Probes");
  ASSERT_TRUE(values) << values.error().to_string();
  EXPECT_EQ((*values)[0], texel(t, 0, 0));
  EXPECT_EQ((*values)[1], texel(t, 3, 1));
  EXPECT_NEAR((*values)[2], (texel(t, 0, 0) + texel(t, 1, 0)) / 2.0, 1e-6);
  EXPECT_EQ((*values)[3], texel(t, 0, 1));
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

Result<RenderOutput> draw_lut_program(const TextureResolver* textures, uint32_t dimensions = 2) {
  auto program = compile_glsl(passthrough_vertex_shader, probe_fragment_shader(dimensions));
  if (!program) return std::unexpected(program.error());
  const MapResolver uniforms({{"coords", std::vector<float>(size_t(kMaxProbes) * 4, 0.5f)}});
  return draw_textured(*program, full_screen_quad(), uniforms, textures, 4, 1);
}

TEST(VulkanTexture, MissingTextureIsAnErrorNamingTheSampler) {
  const MapTextureResolver textures({{"other", kTexture2D}});
  auto out = draw_lut_program(&textures);
  ASSERT_FALSE(out);
  const std::string text = out.error().to_string();
  EXPECT_NE(text.find("'lut'"), std::string::npos) << text;
  EXPECT_NE(text.find("no texture bound"), std::string::npos) << text;  // the resolver's words are kept
  EXPECT_EQ(out.error().stage, "bind") << text;
}

TEST(VulkanTexture, NoResolverIsAnErrorNamingTheSampler) {
  auto out = draw_lut_program(nullptr);
  ASSERT_FALSE(out);
  const std::string text = out.error().to_string();
  EXPECT_NE(text.find("'lut'"), std::string::npos) << text;
  EXPECT_EQ(out.error().stage, "vulkan") << text;
}

TEST(VulkanTexture, DimensionMismatchIsAnError) {
  const MapTextureResolver textures({{"lut", make_texture("volume", 3, 2, 2, 2, std::vector<float>(8, 0.5f))}});
  auto out = draw_lut_program(&textures, 2);
  ASSERT_FALSE(out);
  const std::string text = out.error().to_string();
  EXPECT_NE(text.find("'lut'"), std::string::npos) << text;
  EXPECT_NE(text.find("'volume' is 3D"), std::string::npos) << text;
  EXPECT_NE(text.find("as 2D"), std::string::npos) << text;
}

TEST(VulkanTexture, TexelCountMismatchIsAnError) {
  const MapTextureResolver textures({{"lut", make_texture("short", 2, 4, 2, 1, std::vector<float>(7, 0.5f))}});
  auto out = draw_lut_program(&textures, 2);
  ASSERT_FALSE(out);
  const std::string text = out.error().to_string();
  EXPECT_NE(text.find("'lut'"), std::string::npos) << text;
  EXPECT_NE(text.find("needs 8 texels but has 7"), std::string::npos) << text;
}

TEST(VulkanTexture, UnusedExtentsMustBeOne) {
  const MapTextureResolver textures({{"lut", make_texture("flat", 2, 2, 2, 2, std::vector<float>(8, 0.5f))}});
  auto out = draw_lut_program(&textures, 2);
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

// ---- Filtering precision: the driver against exact linear interpolation ----------------

struct FilterError {
  double max_abs = 0;
  double mean_abs = 0;
  int samples = 0;
};

Result<FilterError> measure_filter_error(const Texture& t) {
  auto program = compile_glsl(passthrough_vertex_shader, measuring_fragment_shader(t.dimensions));
  if (!program) return std::unexpected(program.error());
  const MapTextureResolver textures({{"lut", t}});
  const MapResolver no_uniforms;
  constexpr int size = 128;
  auto out = draw_textured(*program, full_screen_quad(), no_uniforms, &textures, size, size);
  if (!out) return std::unexpected(out.error());
  FilterError e;
  double sum = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float* p = out->image.pixel(x, y);
      const double error = std::abs(double(p[0]) - linear_reference(t, p[1], p[2], p[3]));
      e.max_abs = std::max(e.max_abs, error);
      sum += error;
      ++e.samples;
    }
  e.mean_abs = sum / e.samples;
  return e;
}

TEST(VulkanTexture, FilteringErrorAgainstExactLinearInterpolation) {
  // Texels uniform in [0, 1): an error is also relative to the LUT's range. The sizes
  // are the largest the book's LUT cases use.
  const std::vector<Texture> textures = {
      random_texture("lut1d", 1, 256, 1, 1, 1),
      random_texture("lut2d", 2, 256, 64, 1, 2),
      random_texture("lut3d", 3, 64, 64, 64, 3),
  };
  for (const Texture& t : textures) {
    auto e = measure_filter_error(t);
    ASSERT_TRUE(e) << e.error().to_string();
    std::printf("[ lavapipe ] %uD %ux%ux%u R32F linear filtering: max |error| %.3g, mean %.3g over %d samples\n",
                t.dimensions, t.width, t.height, t.depth, e->max_abs, e->mean_abs, e->samples);
    RecordProperty(t.name + "_max_abs_error", std::to_string(e->max_abs));
    // A bound that still fails a nearest-texel or 8-bit-weight filter by orders of magnitude.
    EXPECT_LT(e->max_abs, 1e-5) << t.name;
  }
}

}  // namespace
}  // namespace shaderbed::vulkan_test
