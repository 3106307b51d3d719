#pragma once
// Shared by the Vulkan and GL tests of file-style textures (RGBA, 8-bit, sRGB, mip
// levels, cube maps) and their sampler settings: probe shaders that write what one
// texture lookup returns to one pixel (GLSL sampler2D/samplerCube, and HLSL SM5
// Texture2D + SamplerState), a resolver with settings per sampler, and the checks each
// backend runs through its own draw function. Expected values are exact texels or exact
// means of two texels, so a wrong filter, address mode, level or decode cannot pass.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "backends/Backend.h"
#include "compile/Compiler.h"

namespace shaderbed::file_texture_probes {

constexpr int kMaxProbes = 16;
using Rgba = std::array<float, 4>;

// u, v (or a cube direction x, y, z) and the level of detail.
struct Probe {
  float x = 0, y = 0, z = 0, lod = 0;
};

// Pixel i of an N x 1 target samples `tex` at probes[i] (textureLod) and writes RGBA.
inline std::string glsl_probe(bool cube) {
  return std::string("#version 450\n") + "layout(std140, binding = 0) uniform Probes { vec4 coords[" +
         std::to_string(kMaxProbes) + "]; };\n" + "layout(binding = 1) uniform " + (cube ? "samplerCube" : "sampler2D") +
         " tex;\n" + "layout(location = 0) out vec4 colour;\n" +
         "void main() {\n  vec4 c = coords[int(gl_FragCoord.x)];\n  colour = textureLod(tex, " +
         (cube ? "c.xyz, c.w" : "c.xy, c.w") + ");\n}\n";
}

// The same probe as an SM5 author writes it: a cbuffer, Texture2D and SamplerState apart.
inline const std::string hlsl_probe_vertex = R"(float4 main(float3 p : POSITION) : SV_Position { return float4(p, 1.0); }
)";
inline const std::string hlsl_probe_fragment = R"(cbuffer Probes : register(b0) { float4 coords[16]; };
Texture2D probeTexture : register(t0);
SamplerState probeSampler : register(s0);
float4 main(float4 position : SV_Position) : SV_Target {
  float4 c = coords[int(position.x)];
  return probeTexture.SampleLevel(probeSampler, c.xy, c.w);
}
)";

inline Result<CompiledProgram> compile_hlsl_probe() {
  ProgramSource source{.language = Language::hlsl,
                       .vertex = {.stage = Stage::vertex, .path = "probe_vs.hlsl", .text = hlsl_probe_vertex},
                       .fragment = {.stage = Stage::fragment, .path = "probe_ps.hlsl", .text = hlsl_probe_fragment}};
  return compile_program(source, true);
}

inline std::vector<float> probe_coords(const std::vector<Probe>& probes) {
  std::vector<float> coords(size_t(kMaxProbes) * 4, 0.0f);
  for (size_t p = 0; p < probes.size() && p < size_t(kMaxProbes); ++p) {
    coords[p * 4 + 0] = probes[p].x;
    coords[p * 4 + 1] = probes[p].y;
    coords[p * 4 + 2] = probes[p].z;
    coords[p * 4 + 3] = probes[p].lod;
  }
  return coords;
}

// Textures and settings by sampler name; a name without settings gets the defaults.
class SettingsResolver final : public TextureResolver {
 public:
  SettingsResolver(std::map<std::string, Texture> textures, std::map<std::string, SamplerSettings> settings = {})
      : textures_(std::move(textures)), settings_(std::move(settings)) {}
  Result<const Texture*> texture(const SamplerBinding& sampler) const override {
    auto it = textures_.find(sampler.name);
    if (it == textures_.end()) return fail(ErrorStage::bind, "no texture bound");
    return &it->second;
  }
  Result<SamplerSettings> settings(const SamplerBinding& sampler) const override {
    auto it = settings_.find(sampler.name);
    return it == settings_.end() ? SamplerSettings{} : it->second;
  }

 private:
  std::map<std::string, Texture> textures_;
  std::map<std::string, SamplerSettings> settings_;
};

// The first `count` pixels of the image's first row: probe i's colour is pixel i.
inline std::vector<Rgba> probe_values(const Image& image, int count) {
  std::vector<Rgba> values;
  for (int x = 0; x < count; ++x) {
    const float* p = image.pixel(x, 0);
    values.push_back({p[0], p[1], p[2], p[3]});
  }
  return values;
}

// What a backend's test provides: one draw of `program` with `textures`, the RGBA of
// pixel i for probe i.
using SampleFn = std::function<Result<std::vector<Rgba>>(const CompiledProgram&, const TextureResolver&,
                                                          const std::vector<Probe>&)>;

// 8-bit texels given as bytes, stored as the loader stores them (byte / 255).
inline Texture rgba8(std::string name, uint32_t w, uint32_t h, const std::vector<int>& bytes, bool srgb = false,
                     bool cube = false) {
  Texture t{.name = std::move(name), .dimensions = 2, .width = w, .height = h};
  t.format = srgb ? TexelFormat::rgba8_srgb : TexelFormat::rgba8_unorm;
  t.cube = cube;
  for (int b : bytes) t.texels.push_back(float(b) / 255.0f);
  return t;
}

// A 4 x 1 strip: red, green, blue, white-ish, every byte distinct.
inline Texture strip() {
  return rgba8("tex", 4, 1, {200, 10, 20, 255, 30, 180, 40, 255, 50, 60, 170, 255, 90, 100, 110, 255});
}

inline double byte(int b) { return b / 255.0; }

inline ::testing::AssertionResult near(const Rgba& got, const std::array<double, 4>& want, double tol,
                                       const std::string& what) {
  for (int c = 0; c < 4; ++c)
    if (!(std::abs(got[size_t(c)] - want[size_t(c)]) <= tol))
      return ::testing::AssertionFailure() << what << ": channel " << c << " is " << got[size_t(c)] << ", expected "
                                           << want[size_t(c)] << " (tolerance " << tol << ")";
  return ::testing::AssertionSuccess();
}

// The filtering arithmetic of the drivers (8-bit fixed-point weights in llvmpipe) is
// exact at texel centres and at midpoints to well below one 8-bit step.
constexpr double kCentre = 1e-6, kMidpoint = 1.0 / 512;

// Texel centres give the file's bytes back; nearest at a midpoint picks one texel,
// linear gives the mean of the two.
inline ::testing::AssertionResult check_filters(const SampleFn& sample, const CompiledProgram& program,
                                                const std::string& texture_name, const std::string& sampler_name) {
  Texture t = strip();
  t.name = texture_name;
  SamplerSettings nearest;
  nearest.min_filter = nearest.mag_filter = TextureFilter::nearest;
  const std::vector<Probe> probes = {{0.125f, 0.5f}, {0.375f, 0.5f}, {0.625f, 0.5f}, {0.875f, 0.5f}, {0.5f, 0.5f}};
  const std::array<std::array<double, 4>, 4> texel = {{{byte(200), byte(10), byte(20), 1},
                                                       {byte(30), byte(180), byte(40), 1},
                                                       {byte(50), byte(60), byte(170), 1},
                                                       {byte(90), byte(100), byte(110), 1}}};
  for (bool linear : {false, true}) {
    const SettingsResolver resolver({{texture_name, t}},
                                    {{sampler_name, linear ? SamplerSettings{} : nearest}});
    auto got = sample(program, resolver, probes);
    if (!got) return ::testing::AssertionFailure() << got.error().to_string();
    for (size_t i = 0; i < 4; ++i)
      if (auto ok = near((*got)[i], texel[i], kCentre, "texel centre " + std::to_string(i)); !ok) return ok;
    std::array<double, 4> mid = texel[2];   // nearest at u = 0.5 exactly: texel 2 (floor(0.5 * 4))
    if (linear)
      for (int c = 0; c < 4; ++c) mid[size_t(c)] = (texel[1][size_t(c)] + texel[2][size_t(c)]) / 2;
    if (auto ok = near((*got)[4], mid, kMidpoint, linear ? "linear midpoint" : "nearest midpoint"); !ok) return ok;
  }
  return ::testing::AssertionSuccess();
}

// u = 1.125 and -0.125: wrap reads texel 0 and texel 3, clamp the edge texels 3 and 0,
// mirror texels 3 and 0, border the border colour (opaque white).
inline ::testing::AssertionResult check_address_modes(const SampleFn& sample, const CompiledProgram& program,
                                                      const std::string& texture_name, const std::string& sampler_name) {
  Texture t = strip();
  t.name = texture_name;
  const std::vector<Probe> probes = {{1.125f, 0.5f}, {-0.125f, 0.5f}};
  const std::array<double, 4> first = {byte(200), byte(10), byte(20), 1}, last = {byte(90), byte(100), byte(110), 1},
                              white = {1, 1, 1, 1};
  struct Mode {
    AddressMode mode;
    std::array<double, 4> right, left;
  };
  for (const Mode& m : {Mode{AddressMode::wrap, first, last}, Mode{AddressMode::clamp, last, first},
                        Mode{AddressMode::mirror, last, first}, Mode{AddressMode::border, white, white}}) {
    SamplerSettings s;
    s.min_filter = s.mag_filter = TextureFilter::nearest;
    s.address_u = s.address_v = m.mode;
    s.border_color[0] = s.border_color[1] = s.border_color[2] = s.border_color[3] = 1.0f;
    const SettingsResolver resolver({{texture_name, t}}, {{sampler_name, s}});
    auto got = sample(program, resolver, probes);
    if (!got) return ::testing::AssertionFailure() << to_string(m.mode) << ": " << got.error().to_string();
    if (auto ok = near((*got)[0], m.right, kCentre, std::string(to_string(m.mode)) + " at u = 1.125"); !ok) return ok;
    if (auto ok = near((*got)[1], m.left, kCentre, std::string(to_string(m.mode)) + " at u = -0.125"); !ok) return ok;
  }
  return ::testing::AssertionSuccess();
}

// An sRGB texture is decoded when sampled: byte 188 reads as ((188/255 + 0.055) / 1.055)^2.4,
// alpha stays linear; the same bytes as UNORM read back undecoded.
inline ::testing::AssertionResult check_srgb(const SampleFn& sample, const CompiledProgram& program,
                                             const std::string& texture_name) {
  const auto decode = [](int b) {
    const double v = b / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  };
  for (bool srgb : {true, false}) {
    const Texture t = rgba8(texture_name, 1, 1, {188, 64, 8, 128}, srgb);
    const SettingsResolver resolver({{texture_name, t}});
    auto got = sample(program, resolver, {{0.5f, 0.5f}});
    if (!got) return ::testing::AssertionFailure() << got.error().to_string();
    const std::array<double, 4> want = srgb ? std::array<double, 4>{decode(188), decode(64), decode(8), byte(128)}
                                            : std::array<double, 4>{byte(188), byte(64), byte(8), byte(128)};
    // The drivers decode sRGB approximately (lavapipe: 7.3e-4 off at byte 188), well
    // inside half an 8-bit step; undecoded bytes would be off by 0.23 there.
    if (auto ok = near((*got)[0], want, srgb ? 1.0 / 512 : kCentre, srgb ? "sRGB decode" : "UNORM"); !ok) return ok;
  }
  return ::testing::AssertionSuccess();
}

// Mip levels reach the device and the mip filter decides whether they are read: at
// lod 1 a 2 x 2 texture with a 1 x 1 level of its own reads that level, without a mip
// filter it reads level 0 (nearest, at a texel centre).
inline ::testing::AssertionResult check_mip_levels(const SampleFn& sample, const CompiledProgram& program,
                                                   const std::string& texture_name, const std::string& sampler_name) {
  Texture t{.name = texture_name, .dimensions = 2, .width = 2, .height = 2, .format = TexelFormat::rgba32_float};
  t.texels = {0.1f, 0.2f, 0.3f, 1, 0.1f, 0.2f, 0.3f, 1, 0.1f, 0.2f, 0.3f, 1, 0.1f, 0.2f, 0.3f, 1};
  t.mip_levels = {{0.7f, 0.6f, 0.5f, 0.25f}};
  for (MipFilter mip : {MipFilter::nearest, MipFilter::none}) {
    SamplerSettings s;
    s.min_filter = s.mag_filter = TextureFilter::nearest;
    s.mip_filter = mip;
    const SettingsResolver resolver({{texture_name, t}}, {{sampler_name, s}});
    auto got = sample(program, resolver, {{0.25f, 0.25f, 0, 1.0f}});
    if (!got) return ::testing::AssertionFailure() << got.error().to_string();
    const std::array<double, 4> want =
        mip == MipFilter::none ? std::array<double, 4>{0.1f, 0.2f, 0.3f, 1} : std::array<double, 4>{0.7f, 0.6f, 0.5f, 0.25f};
    if (auto ok = near((*got)[0], want, kCentre, mip == MipFilter::none ? "lod 1 without mip filter" : "lod 1");
        !ok)
      return ok;
  }
  return ::testing::AssertionSuccess();
}

// A cube map's faces in the order +X, -X, +Y, -Y, +Z, -Z: the axis directions read
// each face's one colour.
inline ::testing::AssertionResult check_cube(const SampleFn& sample, const CompiledProgram& program,
                                             const std::string& texture_name) {
  std::vector<int> bytes;
  for (int face = 0; face < 6; ++face)
    for (int texel = 0; texel < 4; ++texel) bytes.insert(bytes.end(), {40 * face + 10, 250 - 30 * face, 7 * face, 255});
  const Texture t = rgba8(texture_name, 2, 2, bytes, false, true);
  const SettingsResolver resolver({{texture_name, t}});
  const std::vector<Probe> probes = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  auto got = sample(program, resolver, probes);
  if (!got) return ::testing::AssertionFailure() << got.error().to_string();
  for (int face = 0; face < 6; ++face)
    if (auto ok = near((*got)[size_t(face)], {byte(40 * face + 10), byte(250 - 30 * face), byte(7 * face), 1}, kCentre,
                       "cube face " + std::to_string(face));
        !ok)
      return ok;
  return ::testing::AssertionSuccess();
}

}  // namespace shaderbed::file_texture_probes
