// Lookup textures on OSMesa/llvmpipe, on every GL path: R32F texels reach the shader
// unchanged at texel centres, linear filtering averages neighbours, clamp-to-edge holds
// outside [0, 1], in 1D, 2D and 3D, from GLSL and DX9-style HLSL (sampler2D + tex2D).
// Native GLSL samplers without layout(binding) get units of their own; the cross path
// checks SPIRV-Cross kept the reflected units; every way a texture can fail to fit its
// sampler is an Error naming the sampler. One test measures the filtering error.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TextureProbes.h"

#include "GlTestSupport.h"
#include "compile/Compiler.h"

namespace shaderbed::gl_test {
namespace {

using namespace texture_probes;

struct UvProbe {
  float u, v = 0.5f, w = 0.5f;
};

Result<RenderOutput> render_textured(const CompiledProgram& program, ShaderPath path, const UniformResolver& uniforms,
                            const TextureResolver* textures, int width, int height) {
  auto backend = gl_backend();
  if (!backend) return std::unexpected(backend.error());
  const Mesh mesh = ndc_rectangle(-1, -1, 1, 1);
  return (*backend)->render(DrawJob{.program = program, .path = path, .mesh = mesh, .uniforms = uniforms,
                                    .width = width, .height = height, .textures = textures});
}

// The sampled value at each probe, from one draw of `program` (which reads the
// coordinates from the member `coords_member` of a vec4 array).
Result<std::vector<float>> sample(const CompiledProgram& program, ShaderPath path, const TextureResolver& textures,
                                  const std::vector<UvProbe>& probes, const std::string& coords_member = "coords") {
  if (probes.size() > size_t(kMaxProbes)) return fail("test", "too many probes");
  std::vector<float> coords(size_t(kMaxProbes) * 4, 0.0f);
  for (size_t p = 0; p < probes.size(); ++p) {
    coords[p * 4 + 0] = probes[p].u;
    coords[p * 4 + 1] = probes[p].v;
    coords[p * 4 + 2] = probes[p].w;
  }
  const MapResolver uniforms({{coords_member, coords}});
  auto out = render_textured(program, path, uniforms, &textures, int(probes.size()), 1);
  if (!out) return std::unexpected(out.error());
  std::vector<float> values;
  for (int x = 0; x < int(probes.size()); ++x) values.push_back(out->image.pixel(x, 0)[0]);
  return values;
}

Result<std::vector<float>> sample_glsl(ShaderPath path, const Texture& texture, const std::vector<UvProbe>& probes) {
  auto program = compile_glsl(kPassThroughVertex, probe_fragment_shader(texture.dimensions));
  if (!program) return std::unexpected(program.error());
  const MapTextureResolver textures({{"lut", texture}});
  return sample(*program, path, textures, probes);
}

// 4 x 2, values chosen so that no mean is a short binary fraction.
const Texture kTexture2D = make_texture("lut2d", 2, 4, 2, 1, {0.1f, 0.7f, 0.35f, 0.9f,     // row 0
                                                              0.45f, 0.2f, 0.65f, 0.05f}); // row 1

class GlLookupTexture : public ::testing::TestWithParam<ShaderPath> {};

TEST_P(GlLookupTexture, TexelCentresReturnTexelsExactly2D) {
  std::vector<UvProbe> probes;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) probes.push_back({(i + 0.5f) / 4, (j + 0.5f) / 2});
  auto values = sample_glsl(GetParam(), kTexture2D, probes);
  ASSERT_TRUE(values) << values.error().to_string();
  for (size_t p = 0; p < probes.size(); ++p) EXPECT_EQ((*values)[p], kTexture2D.texels[p]) << "texel " << p;
}

TEST_P(GlLookupTexture, HalfwayBetweenTexelCentresIsTheMean2D) {
  const Texture& t = kTexture2D;
  const std::vector<UvProbe> probes = {{0.25f, 0.25f}, {0.75f, 0.75f}, {0.125f, 0.5f}, {0.5f, 0.5f}};
  const std::vector<double> expected = {
      (texel(t, 0, 0) + texel(t, 1, 0)) / 2.0,
      (texel(t, 2, 1) + texel(t, 3, 1)) / 2.0,
      (texel(t, 0, 0) + texel(t, 0, 1)) / 2.0,
      (texel(t, 1, 0) + texel(t, 2, 0) + texel(t, 1, 1) + texel(t, 2, 1)) / 4.0,
  };
  auto values = sample_glsl(GetParam(), t, probes);
  ASSERT_TRUE(values) << values.error().to_string();
  for (size_t p = 0; p < probes.size(); ++p) EXPECT_NEAR((*values)[p], expected[p], 1e-6) << "probe " << p;
}

TEST_P(GlLookupTexture, OutsideTheUnitSquareClampsToTheEdgeTexel2D) {
  const Texture& t = kTexture2D;
  const std::vector<UvProbe> probes = {{-0.5f, -0.5f}, {1.5f, 0.25f}, {0.375f, 2.0f}, {-3.0f, 5.0f}, {7.0f, -7.0f}};
  const std::vector<float> expected = {texel(t, 0, 0), texel(t, 3, 0), texel(t, 1, 1), texel(t, 0, 1), texel(t, 3, 0)};
  auto values = sample_glsl(GetParam(), t, probes);
  ASSERT_TRUE(values) << values.error().to_string();
  for (size_t p = 0; p < probes.size(); ++p) EXPECT_EQ((*values)[p], expected[p]) << "probe " << p;
}

TEST_P(GlLookupTexture, ThreeDimensionalTextureFiltersTrilinearly) {
  const Texture t = make_texture("lut3d", 3, 4, 2, 2,
                                 {0.1f, 0.7f, 0.35f, 0.9f, 0.45f, 0.2f, 0.65f, 0.05f,     // z = 0
                                  0.55f, 0.15f, 0.8f, 0.3f, 0.95f, 0.6f, 0.25f, 0.4f});  // z = 1
  double cell_mean = 0;  // texels i 1..2, j 0..1, k 0..1
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 1; i < 3; ++i) cell_mean += texel(t, i, j, k) / 8.0;
  const std::vector<UvProbe> probes = {
      {0.125f, 0.25f, 0.25f}, {0.625f, 0.75f, 0.75f}, {0.875f, 0.25f, 0.75f}, {0.5f, 0.5f, 0.5f}, {-1.0f, 2.0f, 9.0f}};
  auto values = sample_glsl(GetParam(), t, probes);
  ASSERT_TRUE(values) << values.error().to_string();
  EXPECT_EQ((*values)[0], texel(t, 0, 0, 0));
  EXPECT_EQ((*values)[1], texel(t, 2, 1, 1));
  EXPECT_EQ((*values)[2], texel(t, 3, 0, 1));
  EXPECT_NEAR((*values)[3], cell_mean, 1e-6);
  EXPECT_EQ((*values)[4], texel(t, 0, 1, 1));
}

TEST_P(GlLookupTexture, OneDimensionalTextureFiltersLinearly) {
  const Texture t = make_texture("ramp", 1, 8, 1, 1, {0.1f, 0.7f, 0.35f, 0.9f, 0.45f, 0.2f, 0.65f, 0.05f});
  const std::vector<UvProbe> probes = {{0.0625f}, {0.5625f}, {0.25f}, {0.875f}, {-2.0f}, {3.0f}};
  auto values = sample_glsl(GetParam(), t, probes);
  ASSERT_TRUE(values) << values.error().to_string();
  EXPECT_EQ((*values)[0], texel(t, 0));
  EXPECT_EQ((*values)[1], texel(t, 4));
  EXPECT_NEAR((*values)[2], (texel(t, 1) + texel(t, 2)) / 2.0, 1e-6);
  EXPECT_NEAR((*values)[3], (texel(t, 6) + texel(t, 7)) / 2.0, 1e-6);
  EXPECT_EQ((*values)[4], texel(t, 0));
  EXPECT_EQ((*values)[5], texel(t, 7));
}

TEST_P(GlLookupTexture, EachSamplerGetsItsOwnTexture) {
  auto program = compile_glsl(kPassThroughVertex, R"(#version 450
layout(binding = 1) uniform sampler2D first;
layout(binding = 3) uniform sampler2D second;
layout(binding = 2) uniform sampler1D third;
layout(location = 0) out vec4 colour;
void main() {
  colour = vec4(texture(first, vec2(0.75, 0.25)).r, texture(second, vec2(0.25, 0.75)).r, texture(third, 0.75).r, 1.0);
}
)");
  ASSERT_TRUE(program) << program.error().to_string();
  const MapTextureResolver textures({
      {"first", make_texture("first", 2, 2, 2, 1, {1.0f, 2.0f, 3.0f, 4.0f})},
      {"second", make_texture("second", 2, 2, 2, 1, {-1.0f, -2.0f, -3.0f, -4.0f})},
      {"third", make_texture("third", 1, 2, 1, 1, {0.25f, 0.5f})},
  });
  auto out = render_textured(*program, GetParam(), MapResolver{}, &textures, 4, 4);
  ASSERT_TRUE(out) << out.error().to_string();
  const float* p = out->image.pixel(2, 2);
  EXPECT_EQ(p[0], 2.0f);
  EXPECT_EQ(p[1], -3.0f);
  EXPECT_EQ(p[2], 0.5f);
}

const char* const kVertexSamplerVertex = R"(#version 450
layout(location = 0) in vec3 position;
layout(binding = 4) uniform sampler1D ramp;
layout(location = 0) out float from_vertex;
void main() { from_vertex = textureLod(ramp, 0.75, 0.0).r; gl_Position = vec4(position, 1.0); }
)";

const char* const kVertexSamplerFragment = R"(#version 450
layout(binding = 1) uniform sampler2D first;
layout(location = 0) in float from_vertex;
layout(location = 0) out vec4 colour;
void main() { colour = vec4(texture(first, vec2(0.75, 0.25)).r, from_vertex, 0.0, 1.0); }
)";

TEST_P(GlLookupTexture, SamplersOfBothStagesGetTheirTextures) {
  auto program = compile_glsl(kVertexSamplerVertex, kVertexSamplerFragment);
  ASSERT_TRUE(program) << program.error().to_string();
  const MapTextureResolver textures({
      {"ramp", make_texture("ramp", 1, 2, 1, 1, {0.25f, 0.5f})},
      {"first", make_texture("first", 2, 2, 2, 1, {1.0f, 2.0f, 3.0f, 4.0f})},
  });
  auto out = render_textured(*program, GetParam(), MapResolver{}, &textures, 4, 4);
  if (!out && out.error().message.find("both have uniform location") != std::string::npos)
    GTEST_SKIP() << "known compile-stage gap: glslang numbers each stage's sampler locations from 0 "
                    "(needs a per-stage uniform location base): "
                 << out.error().to_string();
  ASSERT_TRUE(out) << out.error().to_string();
  const float* p = out->image.pixel(2, 2);
  EXPECT_EQ(p[0], 2.0f);
  EXPECT_EQ(p[1], 0.5f);
}

Result<RenderOutput> render_lut_program(ShaderPath path, const TextureResolver* textures) {
  auto program = compile_glsl(kPassThroughVertex, probe_fragment_shader(2));
  if (!program) return std::unexpected(program.error());
  const MapResolver uniforms({{"coords", std::vector<float>(size_t(kMaxProbes) * 4, 0.5f)}});
  return render_textured(*program, path, uniforms, textures, 4, 1);
}

TEST_P(GlLookupTexture, MissingTextureIsAnErrorNamingTheSampler) {
  const MapTextureResolver textures({{"other", kTexture2D}});
  auto out = render_lut_program(GetParam(), &textures);
  ASSERT_FALSE(out);
  const std::string text = out.error().to_string();
  EXPECT_NE(text.find("'lut'"), std::string::npos) << text;
  EXPECT_NE(text.find("no texture bound"), std::string::npos) << text;  // the resolver's words are kept
  EXPECT_EQ(out.error().stage, "bind") << text;
  EXPECT_EQ(out.error().backend, "gl") << text;
}

TEST_P(GlLookupTexture, NoResolverIsAnErrorNamingTheSampler) {
  auto out = render_lut_program(GetParam(), nullptr);
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().message.find("'lut'"), std::string::npos) << out.error().to_string();
}

TEST_P(GlLookupTexture, DimensionMismatchIsAnError) {
  const MapTextureResolver textures({{"lut", make_texture("volume", 3, 2, 2, 2, std::vector<float>(8, 0.5f))}});
  auto out = render_lut_program(GetParam(), &textures);
  ASSERT_FALSE(out);
  const std::string text = out.error().to_string();
  EXPECT_NE(text.find("'lut'"), std::string::npos) << text;
  EXPECT_NE(text.find("'volume' is 3D"), std::string::npos) << text;
  EXPECT_NE(text.find("as 2D"), std::string::npos) << text;
}

TEST_P(GlLookupTexture, TexelCountMismatchIsAnError) {
  const MapTextureResolver textures({{"lut", make_texture("short", 2, 4, 2, 1, std::vector<float>(7, 0.5f))}});
  auto out = render_lut_program(GetParam(), &textures);
  ASSERT_FALSE(out);
  const std::string text = out.error().to_string();
  EXPECT_NE(text.find("'lut'"), std::string::npos) << text;
  EXPECT_NE(text.find("needs 8 texels but has 7"), std::string::npos) << text;
}

// ---- Filtering precision: the driver against exact linear interpolation ----------------

TEST_P(GlLookupTexture, FilteringErrorAgainstExactLinearInterpolation) {
  // Texels uniform in [0, 1): an error is also relative to the LUT's range. The sizes
  // are the largest the book's LUT cases use.
  const std::vector<Texture> textures = {
      random_texture("lut1d", 1, 256, 1, 1, 1),
      random_texture("lut2d", 2, 256, 64, 1, 2),
      random_texture("lut3d", 3, 64, 64, 64, 3),
  };
  constexpr int size = 128;
  for (const Texture& t : textures) {
    auto program = compile_glsl(kPassThroughVertex, measuring_fragment_shader(t.dimensions));
    ASSERT_TRUE(program) << program.error().to_string();
    const MapTextureResolver resolver({{"lut", t}});
    auto out = render_textured(*program, GetParam(), MapResolver{}, &resolver, size, size);
    ASSERT_TRUE(out) << out.error().to_string();
    double max_abs = 0, sum = 0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const float* p = out->image.pixel(x, y);
        const double error = std::abs(double(p[0]) - linear_reference(t, p[1], p[2], p[3]));
        max_abs = std::max(max_abs, error);
        sum += error;
      }
    std::printf("[ llvmpipe GL %s ] %uD %ux%ux%u R32F linear filtering: max |error| %.3g, mean %.3g over %d samples\n",
                to_string(GetParam()), t.dimensions, t.width, t.height, t.depth, max_abs, sum / (size * size),
                size * size);
    RecordProperty(t.name + "_max_abs_error", std::to_string(max_abs));
    // Far below what a nearest-texel or low-precision-weight filter produces.
    EXPECT_LT(max_abs, 1e-5) << t.name;
  }
}

INSTANTIATE_TEST_SUITE_P(AllGlslPaths, GlLookupTexture,
                         ::testing::Values(ShaderPath::native_glsl, ShaderPath::spirv, ShaderPath::cross_glsl),
                         [](const auto& info) { return std::string(to_string(info.param)); });

// ---- HLSL ---------------------------------------------------------------------------------

class GlHlslLookupTexture : public ::testing::TestWithParam<ShaderPath> {};

TEST_P(GlHlslLookupTexture, Dx9Sampler2DWithTex2D) {
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
  const Texture& t = kTexture2D;
  const MapTextureResolver textures({{"Lut", t}});
  auto values = sample(*program, GetParam(), textures,
                       {{0.125f, 0.25f}, {0.875f, 0.75f}, {0.25f, 0.25f}, {-1.0f, 1.5f}}, "Probes");
  ASSERT_TRUE(values) << values.error().to_string();
  EXPECT_EQ((*values)[0], texel(t, 0, 0));
  EXPECT_EQ((*values)[1], texel(t, 3, 1));
  EXPECT_NEAR((*values)[2], (texel(t, 0, 0) + texel(t, 1, 0)) / 2.0, 1e-6);
  EXPECT_EQ((*values)[3], texel(t, 0, 1));
}

INSTANTIATE_TEST_SUITE_P(SpirvAndCross, GlHlslLookupTexture,
                         ::testing::Values(ShaderPath::spirv, ShaderPath::cross_glsl),
                         [](const auto& info) { return std::string(to_string(info.param)); });

// ---- Path-specific binding ----------------------------------------------------------------

TEST(GlLookupTextureNative, SamplersWithoutBindingGetTheirOwnUnits) {
  // All three read unit 0, two by default and one by layout(binding = 0); GL cannot tell
  // those apart, so two must move to free units. Left on one unit, the 1D and 2D
  // samplers would also make the draw a GL_INVALID_OPERATION.
  const CompiledProgram program = native_glsl_only(kPassThroughVertex, R"(#version 450
uniform sampler2D first;
uniform sampler2D second;
layout(binding = 0) uniform sampler1D third;
layout(location = 0) out vec4 colour;
void main() {
  colour = vec4(texture(first, vec2(0.25)).r, texture(second, vec2(0.25)).r, texture(third, 0.25).r, 1.0);
}
)");
  const MapTextureResolver textures({
      {"first", make_texture("first", 2, 1, 1, 1, {1.5f})},
      {"second", make_texture("second", 2, 1, 1, 1, {-2.5f})},
      {"third", make_texture("third", 1, 1, 1, 1, {7.0f})},
  });
  auto out = render_textured(program, ShaderPath::native_glsl, MapResolver{}, &textures, 4, 4);
  ASSERT_TRUE(out) << out.error().to_string();
  const float* p = out->image.pixel(1, 1);
  EXPECT_EQ(p[0], 1.5f);
  EXPECT_EQ(p[1], -2.5f);
  EXPECT_EQ(p[2], 7.0f);
}

TEST(GlLookupTextureNative, SamplerArrayIsAnError) {
  const CompiledProgram program = native_glsl_only(kPassThroughVertex, R"(#version 450
uniform sampler2D luts[2];
layout(location = 0) out vec4 colour;
void main() { colour = texture(luts[0], vec2(0.5)) + texture(luts[1], vec2(0.5)); }
)");
  const MapTextureResolver textures({{"luts", kTexture2D}});
  auto out = render_textured(program, ShaderPath::native_glsl, MapResolver{}, &textures, 4, 4);
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().message.find("'luts' is an array"), std::string::npos) << out.error().to_string();
}

TEST(GlLookupTextureCross, UnitThatDisagreesWithReflectionIsAnError) {
  auto program = compile_glsl(kPassThroughVertex, probe_fragment_shader(2));
  ASSERT_TRUE(program) << program.error().to_string();
  ASSERT_EQ(program->fragment_gl.reflection.samplers.size(), 1u);
  // As if SPIRV-Cross had dropped or changed the sampler's layout(binding).
  program->fragment_gl.reflection.samplers[0].binding += 5;
  const MapTextureResolver textures({{"lut", kTexture2D}});
  const MapResolver uniforms({{"coords", std::vector<float>(size_t(kMaxProbes) * 4, 0.5f)}});
  auto out = render_textured(*program, ShaderPath::cross_glsl, uniforms, &textures, 4, 1);
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().message.find("layout(binding)"), std::string::npos) << out.error().to_string();
  EXPECT_NE(out.error().message.find("cross path"), std::string::npos) << out.error().to_string();
}

// Rewrites the Location decoration of every UniformConstant variable of a module.
void move_uniform_locations(std::vector<uint32_t>& spirv, uint32_t location) {
  std::vector<uint32_t> uniform_constants;
  for (size_t at = 5; at < spirv.size(); at += spirv[at] >> 16)
    if ((spirv[at] & 0xffff) == 59 && spirv[at + 3] == 0) uniform_constants.push_back(spirv[at + 2]);  // OpVariable
  for (size_t at = 5; at < spirv.size(); at += spirv[at] >> 16)
    if ((spirv[at] & 0xffff) == 71 && spirv[at + 2] == 30 &&  // OpDecorate id Location
        std::ranges::find(uniform_constants, spirv[at + 1]) != uniform_constants.end())
      spirv[at + 3] = location;
}

TEST(GlLookupTextureSpirv, SamplersOfTwoStagesOnOneUniformLocationIsAnError) {
  auto program = compile_glsl(kVertexSamplerVertex, kVertexSamplerFragment);
  ASSERT_TRUE(program) << program.error().to_string();
  // Whatever locations the compile stage chose, put both stages' samplers on one.
  move_uniform_locations(program->vertex_gl.spirv, 3);
  move_uniform_locations(program->fragment_gl.spirv, 3);
  const MapTextureResolver textures({
      {"ramp", make_texture("ramp", 1, 2, 1, 1, {0.25f, 0.5f})},
      {"first", make_texture("first", 2, 2, 2, 1, {1.0f, 2.0f, 3.0f, 4.0f})},
  });
  auto out = render_textured(*program, ShaderPath::spirv, MapResolver{}, &textures, 4, 4);
  ASSERT_FALSE(out) << "GL would silently link 'ramp' and 'first' as one uniform";
  const std::string text = out.error().to_string();
  EXPECT_NE(text.find("'ramp'"), std::string::npos) << text;
  EXPECT_NE(text.find("'first'"), std::string::npos) << text;
  EXPECT_NE(text.find("uniform location 3"), std::string::npos) << text;
}

TEST(GlLookupTextureSpirv, TwoSamplersOnOneUnitIsAnError) {
  auto program = compile_glsl(kPassThroughVertex, R"(#version 450
layout(binding = 1) uniform sampler2D first;
layout(binding = 2) uniform sampler3D second;
layout(location = 0) out vec4 colour;
void main() { colour = texture(first, vec2(0.5)) + texture(second, vec3(0.5)); }
)");
  ASSERT_TRUE(program) << program.error().to_string();
  ASSERT_EQ(program->fragment_gl.reflection.samplers.size(), 2u);
  program->fragment_gl.reflection.samplers[1].binding = program->fragment_gl.reflection.samplers[0].binding;
  const MapTextureResolver textures({{"first", kTexture2D}, {"second", make_texture("v", 3, 1, 1, 1, {1.0f})}});
  auto out = render_textured(*program, ShaderPath::spirv, MapResolver{}, &textures, 4, 4);
  ASSERT_FALSE(out);
  const std::string text = out.error().to_string();
  EXPECT_NE(text.find("'first'"), std::string::npos) << text;
  EXPECT_NE(text.find("'second'"), std::string::npos) << text;
  EXPECT_NE(text.find("texture unit 1"), std::string::npos) << text;
}

}  // namespace
}  // namespace shaderbed::gl_test
