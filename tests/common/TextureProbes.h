#pragma once
// Shared by the Vulkan and GL texture tests: LUT-like textures, the exact linear filter
// they are checked against, a probe shader (valid GLSL for both APIs) that samples a
// texture at per-pixel coordinates, and the checks both backends run with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "MapResolvers.h"
#include "backends/Backend.h"
#include "compile/Compiler.h"
#include "lut/LookupTexture.h"

namespace shaderbed::texture_probes {

constexpr int kMaxProbes = 16;

inline Texture make_texture(std::string name, uint32_t dimensions, uint32_t width, uint32_t height, uint32_t depth,
                     std::vector<float> texels) {
  return Texture{.name = std::move(name), .dimensions = dimensions, .width = width, .height = height, .depth = depth,
                 .texels = std::move(texels)};
}

inline Texture random_texture(std::string name, uint32_t dimensions, uint32_t width, uint32_t height, uint32_t depth,
                       uint32_t seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> texels(size_t(width) * height * depth);
  for (float& t : texels) t = unit(generator);
  return make_texture(std::move(name), dimensions, width, height, depth, std::move(texels));
}

inline float texel(const Texture& t, int i, int j = 0, int k = 0) {
  i = std::clamp(i, 0, int(t.width) - 1);
  j = std::clamp(j, 0, int(t.height) - 1);
  k = std::clamp(k, 0, int(t.depth) - 1);
  return t.texels[(size_t(k) * t.height + size_t(j)) * t.width + size_t(i)];
}

// Exact (double) linear filtering with clamp-to-edge and texel centres at (i + 0.5) / n:
// the harness's own CPU sampler (lut/LookupTexture.h), which the LUT tolerances use too.
inline double linear_reference(const Texture& t, double u, double v = 0.5, double w = 0.5) {
  const double coords[3] = {u, v, w};
  return sample_linear(t, coords);
}

inline const char* sampler_type(uint32_t dimensions) {
  return dimensions == 1 ? "sampler1D" : dimensions == 2 ? "sampler2D" : "sampler3D";
}

// Pixel x of an N x 1 target samples `lut` at coords[x] and writes the value to red.
inline std::string probe_fragment_shader(uint32_t dimensions) {
  const char* swizzle = dimensions == 1 ? ".x" : dimensions == 2 ? ".xy" : ".xyz";
  return std::string("#version 450\n") +
         "layout(std140, binding = 0) uniform Probes { vec4 coords[" + std::to_string(kMaxProbes) + "]; };\n" +
         "layout(binding = 1) uniform " + sampler_type(dimensions) + " lut;\n" +
         "layout(location = 0) out vec4 colour;\n" +
         "void main() { colour = vec4(texture(lut, coords[int(gl_FragCoord.x)]" + swizzle + ").r, 0.0, 0.0, 1.0); }\n";
}

// Quasi-random coordinates in [-0.1, 1.1]^n per pixel (R2/R3 sequences of the pixel
// position); the shader writes the coordinate it used next to the sample, so the
// reference is computed from exactly the float the sampler saw.
inline std::string measuring_fragment_shader(uint32_t dimensions) {
  const std::string coordinate =
      dimensions == 1   ? "float c = fract(dot(p, vec2(0.7548776662, 0.5698402910))) * 1.2 - 0.1;\n"
                          "colour = vec4(texture(lut, c).r, c, 0.5, 0.5);\n"
      : dimensions == 2 ? "vec2 c = fract(vec2(dot(p, vec2(0.7548776662, 0.5698402910)), "
                          "dot(p, vec2(0.5698402910, 0.3248198))) + 0.1 * p.yx) * 1.2 - 0.1;\n"
                          "colour = vec4(texture(lut, c).r, c, 0.5);\n"
                        : "vec3 c = fract(vec3(dot(p, vec2(0.8191725134, 0.6710436067)), "
                          "dot(p, vec2(0.5497004779, 0.8191725134)), dot(p, vec2(0.6710436067, 0.5497004779))) "
                          "+ 0.1 * p.yxy) * 1.2 - 0.1;\n"
                          "colour = vec4(texture(lut, c).r, c);\n";
  return std::string("#version 450\n") + "layout(binding = 0) uniform " + sampler_type(dimensions) + " lut;\n" +
         "layout(location = 0) out vec4 colour;\n" + "void main() {\n  vec2 p = gl_FragCoord.xy;\n  " + coordinate +
         "}\n";
}

// ---- The checks both backends run --------------------------------------------------------

// What a backend's test supplies: its compile of a GLSL fragment shader (beside a vertex
// shader passing NDC positions through), its draw over a whole width x height target,
// and the name its errors carry.
struct TextureBench {
  std::function<Result<CompiledProgram>(const std::string& fragment)> compile_fragment;
  std::function<Result<RenderOutput>(const CompiledProgram&, const UniformResolver&, const TextureResolver*, int width,
                                     int height)>
      draw;
  std::string backend;
};

struct UvProbe {
  float u, v = 0.5f, w = 0.5f;
};

// 4 x 2, values chosen so that no mean is a short binary fraction.
inline const Texture kTexture2D = make_texture("lut2d", 2, 4, 2, 1, {0.1f, 0.7f, 0.35f, 0.9f,     // row 0
                                                                     0.45f, 0.2f, 0.65f, 0.05f}); // row 1

// The sampled value at each probe, from one draw of `program` (which reads the
// coordinates from the member `coords_member` of a vec4 array).
inline Result<std::vector<float>> sample(const TextureBench& bench, const CompiledProgram& program,
                                         const TextureResolver& textures, const std::vector<UvProbe>& probes,
                                         const std::string& coords_member = "coords") {
  if (probes.size() > size_t(kMaxProbes)) return fail(ErrorStage::none, "test: too many probes");
  std::vector<float> coords(size_t(kMaxProbes) * 4, 0.0f);
  for (size_t p = 0; p < probes.size(); ++p) {
    coords[p * 4 + 0] = probes[p].u;
    coords[p * 4 + 1] = probes[p].v;
    coords[p * 4 + 2] = probes[p].w;
  }
  const test::MapResolver uniforms({{coords_member, coords}});
  auto out = bench.draw(program, uniforms, &textures, int(probes.size()), 1);
  if (!out) return std::unexpected(out.error());
  std::vector<float> values;
  for (int x = 0; x < int(probes.size()); ++x) values.push_back(out->image.pixel(x, 0)[0]);
  return values;
}

// `texture` sampled at each probe by probe_fragment_shader.
inline Result<std::vector<float>> sample_probes(const TextureBench& bench, const Texture& texture,
                                                const std::vector<UvProbe>& probes) {
  auto program = bench.compile_fragment(probe_fragment_shader(texture.dimensions));
  if (!program) return std::unexpected(program.error());
  const test::MapTextureResolver textures({{"lut", texture}});
  return sample(bench, *program, textures, probes);
}

inline void expect_texel_centres_exact_2d(const TextureBench& bench) {
  std::vector<UvProbe> probes;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) probes.push_back({(i + 0.5f) / 4, (j + 0.5f) / 2});
  auto values = sample_probes(bench, kTexture2D, probes);
  ASSERT_TRUE(values) << values.error().to_string();
  for (size_t p = 0; p < probes.size(); ++p) EXPECT_EQ((*values)[p], kTexture2D.texels[p]) << "texel " << p;
}

inline void expect_halfway_is_the_mean_2d(const TextureBench& bench) {
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
  auto values = sample_probes(bench, t, probes);
  ASSERT_TRUE(values) << values.error().to_string();
  for (size_t p = 0; p < probes.size(); ++p) EXPECT_NEAR((*values)[p], expected[p], 1e-6) << "probe " << p;
}

inline void expect_clamp_to_edge_2d(const TextureBench& bench) {
  const Texture& t = kTexture2D;
  const std::vector<UvProbe> probes = {{-0.5f, -0.5f}, {1.5f, 0.25f}, {0.375f, 2.0f}, {-3.0f, 5.0f}, {7.0f, -7.0f}};
  const std::vector<float> expected = {texel(t, 0, 0), texel(t, 3, 0), texel(t, 1, 1), texel(t, 0, 1), texel(t, 3, 0)};
  auto values = sample_probes(bench, t, probes);
  ASSERT_TRUE(values) << values.error().to_string();
  for (size_t p = 0; p < probes.size(); ++p) EXPECT_EQ((*values)[p], expected[p]) << "probe " << p;
}

inline void expect_trilinear_3d(const TextureBench& bench) {
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
  auto values = sample_probes(bench, t, probes);
  ASSERT_TRUE(values) << values.error().to_string();
  EXPECT_EQ((*values)[0], texel(t, 0, 0, 0));
  EXPECT_EQ((*values)[1], texel(t, 2, 1, 1));
  EXPECT_EQ((*values)[2], texel(t, 3, 0, 1));
  EXPECT_NEAR((*values)[3], cell_mean, 1e-6);
  EXPECT_EQ((*values)[4], texel(t, 0, 1, 1));
}

inline void expect_linear_1d(const TextureBench& bench) {
  const Texture t = make_texture("ramp", 1, 8, 1, 1, {0.1f, 0.7f, 0.35f, 0.9f, 0.45f, 0.2f, 0.65f, 0.05f});
  const std::vector<UvProbe> probes = {{0.0625f}, {0.5625f}, {0.25f}, {0.875f}, {-2.0f}, {3.0f}};
  auto values = sample_probes(bench, t, probes);
  ASSERT_TRUE(values) << values.error().to_string();
  EXPECT_EQ((*values)[0], texel(t, 0));
  EXPECT_EQ((*values)[1], texel(t, 4));
  EXPECT_NEAR((*values)[2], (texel(t, 1) + texel(t, 2)) / 2.0, 1e-6);
  EXPECT_NEAR((*values)[3], (texel(t, 6) + texel(t, 7)) / 2.0, 1e-6);
  EXPECT_EQ((*values)[4], texel(t, 0));
  EXPECT_EQ((*values)[5], texel(t, 7));
}

// DX9-style HLSL: a sampler2D read by tex2D at coordinates from a float4 array.
inline Result<CompiledProgram> compile_dx9_probe() {
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
  return compile_program(source);
}

inline void expect_dx9_tex2d_filters(const TextureBench& bench, const CompiledProgram& program) {
  const Texture& t = kTexture2D;
  const test::MapTextureResolver textures({{"Lut", t}});
  auto values = sample(bench, program, textures, {{0.125f, 0.25f}, {0.875f, 0.75f}, {0.25f, 0.25f}, {-1.0f, 1.5f}},
                       "Probes");
  ASSERT_TRUE(values) << values.error().to_string();
  EXPECT_EQ((*values)[0], texel(t, 0, 0));
  EXPECT_EQ((*values)[1], texel(t, 3, 1));
  EXPECT_NEAR((*values)[2], (texel(t, 0, 0) + texel(t, 1, 0)) / 2.0, 1e-6);
  EXPECT_EQ((*values)[3], texel(t, 0, 1));
}

// The 2D probe program drawn with `textures` (or none): the way a texture fails to fit.
inline Result<RenderOutput> draw_probe_program(const TextureBench& bench, const TextureResolver* textures) {
  auto program = bench.compile_fragment(probe_fragment_shader(2));
  if (!program) return std::unexpected(program.error());
  const test::MapResolver uniforms({{"coords", std::vector<float>(size_t(kMaxProbes) * 4, 0.5f)}});
  return bench.draw(*program, uniforms, textures, 4, 1);
}

// A binding error names the sampler and keeps `words`, and says which backend it was.
inline void expect_binding_error(const TextureBench& bench, const TextureResolver* textures,
                                 const std::vector<std::string>& words) {
  auto out = draw_probe_program(bench, textures);
  ASSERT_FALSE(out);
  const std::string text = out.error().to_string();
  EXPECT_NE(text.find("'lut'"), std::string::npos) << text;
  for (const std::string& w : words) EXPECT_NE(text.find(w), std::string::npos) << text;
  EXPECT_EQ(out.error().backend, bench.backend) << text;
}

inline void expect_missing_texture_error(const TextureBench& bench) {
  const test::MapTextureResolver textures({{"other", kTexture2D}});
  expect_binding_error(bench, &textures, {"no texture bound"});  // the resolver's words are kept
}

inline void expect_no_resolver_error(const TextureBench& bench) { expect_binding_error(bench, nullptr, {}); }

inline void expect_dimension_mismatch_error(const TextureBench& bench) {
  const test::MapTextureResolver textures({{"lut", make_texture("volume", 3, 2, 2, 2, std::vector<float>(8, 0.5f))}});
  expect_binding_error(bench, &textures, {"'volume' is 3D", "as 2D"});
}

inline void expect_texel_count_error(const TextureBench& bench) {
  const test::MapTextureResolver textures({{"lut", make_texture("short", 2, 4, 2, 1, std::vector<float>(7, 0.5f))}});
  expect_binding_error(bench, &textures, {"needs 8 texels but has 7"});
}

// The driver's linear filtering against exact interpolation in double, on random R32F
// textures of the largest sizes the book's LUT cases use (texels uniform in [0, 1), so an
// error is also relative to the LUT's range): within 1e-5 everywhere. `label` names the
// driver in the printout.
inline void expect_filtering_close_to_exact(const TextureBench& bench, const std::string& label) {
  const std::vector<Texture> textures = {
      random_texture("lut1d", 1, 256, 1, 1, 1),
      random_texture("lut2d", 2, 256, 64, 1, 2),
      random_texture("lut3d", 3, 64, 64, 64, 3),
  };
  constexpr int size = 128;
  for (const Texture& t : textures) {
    auto program = bench.compile_fragment(measuring_fragment_shader(t.dimensions));
    ASSERT_TRUE(program) << program.error().to_string();
    const test::MapTextureResolver resolver({{"lut", t}});
    auto out = bench.draw(*program, test::MapResolver{}, &resolver, size, size);
    ASSERT_TRUE(out) << out.error().to_string();
    double max_abs = 0, sum = 0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const float* p = out->image.pixel(x, y);
        const double error = std::abs(double(p[0]) - linear_reference(t, p[1], p[2], p[3]));
        max_abs = std::max(max_abs, error);
        sum += error;
      }
    std::printf("[ %s ] %uD %ux%ux%u R32F linear filtering: max |error| %.3g, mean %.3g over %d samples\n",
                label.c_str(), t.dimensions, t.width, t.height, t.depth, max_abs, sum / (size * size), size * size);
    ::testing::Test::RecordProperty(t.name + "_max_abs_error", std::to_string(max_abs));
    // Fails a nearest-texel or 8-bit-weight filter by orders of magnitude.
    EXPECT_LT(max_abs, 1e-5) << t.name;
  }
}

}  // namespace shaderbed::texture_probes
