#pragma once
// Shared by the Vulkan and GL render-state tests: a small DX9 effect whose pass states a
// test writes, compiled by the real effect front end, drawn on the book's scene (GLUT
// shapes, the D3D-style camera) by a real backend with the pass's RenderState, the image
// measures the tests compare, and the checks both backends run.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <string>

#include "backends/Backend.h"
#include "compile/Compiler.h"
#include "scene/Primitives.h"
#include "scene/Scene.h"

namespace shaderbed::test {

constexpr int kStateImageSize = 48;

// The normal as a colour (front and back faces differ), alpha from the compile argument.
inline std::string render_state_effect(const std::string& states, const std::string& alpha = "1.0") {
  return "// A render-state probe (no lighting model): the normal as a colour.\n"
         "float4x4 Transform : WORLDVIEWPROJECTION;\n"
         "struct V { float4 p : POSITION; float3 n : TEXCOORD0; };\n"
         "V VS(float4 p : POSITION, float3 n : NORMAL) { V o; o.p = mul(Transform, p); o.n = n; return o; }\n"
         "float4 PS(float3 n : TEXCOORD0, uniform float alpha) : COLOR0 { return float4(normalize(n) * 0.5 + 0.5, alpha); }\n"
         "technique T {\n  pass P {\n    VertexShader = compile vs_2_0 VS();\n    PixelShader = compile ps_2_0 PS(" +
         alpha + ");\n    " + states + "\n  }\n}\n";
}

class TransformResolver final : public UniformResolver {
 public:
  explicit TransformResolver(int size = kStateImageSize) {
    SceneSetup scene;
    scene.width = scene.height = size;
    transform_ = scene_quantities(scene).at("transform");
  }
  Result<std::vector<double>> value(const UniformBlock&, const UniformMember& member) const override {
    if (member.name == "Transform") return transform_;
    return fail(ErrorStage::bind, "no value for '" + member.name + "'");
  }

 private:
  std::vector<double> transform_;
};

inline Result<CompiledProgram> compile_state_effect(const std::string& states, const std::string& alpha = "1.0") {
  const std::string text = render_state_effect(states, alpha);
  ProgramSource source{.language = Language::hlsl,
                       .vertex = {.stage = Stage::vertex, .path = "states.fx", .text = text},
                       .fragment = {.stage = Stage::fragment, .path = "states.fx", .text = text}};
  return compile_program(source);
}

// Draws `shape` with the effect's pass: its RenderState goes into the DrawJob, as the
// runner does it.
inline Result<Image> draw_with_states(Backend& backend, ShaderPath path, const std::string& shape,
                                      const std::string& states, const std::string& alpha = "1.0",
                                      int size = kStateImageSize) {
  auto program = compile_state_effect(states, alpha);
  if (!program) return std::unexpected(program.error());
  auto mesh = make_shape(shape, Tessellation::low);
  if (!mesh) return fail(ErrorStage::none, "test: no shape " + shape);
  const TransformResolver uniforms(size);
  DrawJob job{.program = *program, .path = path, .mesh = *mesh, .uniforms = uniforms, .width = size, .height = size};
  job.render_state = program->render_state;
  auto out = backend.render(job);
  if (!out) return std::unexpected(out.error());
  return std::move(out->image);
}

// An effect whose pixel shader reads one texel-exact spot, u = 1.25, through a
// sampler_state with POINT filtering and the given AddressU (and BorderColor).
inline std::string sampler_state_effect(const std::string& address_u) {
  return "// A sampler_state probe (no lighting model): one texture lookup outside [0, 1].\n"
         "float4x4 Transform;\n"
         "texture Tex;\n"
         "sampler S = sampler_state {\n  Texture = <Tex>;\n  MinFilter = POINT;\n  MagFilter = POINT;\n"
         "  MipFilter = NONE;\n  AddressU = " + address_u + ";\n  AddressV = CLAMP;\n  BorderColor = 0xFFFFFFFF;\n};\n"
         "float4 VS(float4 p : POSITION) : POSITION { return mul(Transform, p); }\n"
         "float4 PS() : COLOR0 { return tex2D(S, float2(1.25, 0.5)); }\n"
         "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";
}

// Every sampler gets one 2x1 texture, red then green, sampled as the program's
// sampler_state says (what CaseTextures does with the effect's settings).
class EffectSamplerTextures final : public TextureResolver {
 public:
  explicit EffectSamplerTextures(const CompiledProgram& program) : settings_(program.sampler_settings) {
    texture_.name = "Tex";
    texture_.width = 2;
    texture_.format = TexelFormat::rgba32_float;
    texture_.texels = {1, 0, 0, 1, 0, 1, 0, 1};
  }
  Result<const Texture*> texture(const SamplerBinding&) const override { return &texture_; }
  Result<SamplerSettings> settings(const SamplerBinding& sampler) const override {
    auto it = settings_.find(sampler.name);
    if (it == settings_.end()) return fail(ErrorStage::bind, "no sampler_state for '" + sampler.name + "'");
    return it->second;
  }

 private:
  std::map<std::string, SamplerSettings> settings_;
  Texture texture_;
};

// The colour of the first covered pixel of the sphere drawn with the probe effect.
inline Result<std::array<float, 4>> sampled_colour(Backend& backend, ShaderPath path, const std::string& address_u) {
  const std::string text = sampler_state_effect(address_u);
  ProgramSource source{.language = Language::hlsl,
                       .vertex = {.stage = Stage::vertex, .path = "sampler.fx", .text = text},
                       .fragment = {.stage = Stage::fragment, .path = "sampler.fx", .text = text}};
  auto program = compile_program(source);
  if (!program) return std::unexpected(program.error());
  auto mesh = make_shape("sphere", Tessellation::low);
  const TransformResolver uniforms;
  const EffectSamplerTextures textures(*program);
  DrawJob job{.program = *program, .path = path, .mesh = *mesh, .uniforms = uniforms, .width = kStateImageSize,
              .height = kStateImageSize, .textures = &textures};
  auto out = backend.render(job);
  if (!out) return std::unexpected(out.error());
  for (size_t i = 0; i < out->image.coverage.size(); ++i)
    if (out->image.coverage[i])
      return std::array<float, 4>{out->image.rgba[i * 4], out->image.rgba[i * 4 + 1], out->image.rgba[i * 4 + 2],
                                  out->image.rgba[i * 4 + 3]};
  return fail(ErrorStage::none, "test: nothing drawn");
}

inline int covered(const Image& image) {
  int n = 0;
  for (uint8_t c : image.coverage) n += c;
  return n;
}

// Pixels covered in either image whose coverage or colour differ by more than `tolerance`.
inline int differing_pixels(const Image& a, const Image& b, float tolerance = 1e-4f) {
  int n = 0;
  for (size_t i = 0; i < a.coverage.size(); ++i) {
    if (!a.coverage[i] && !b.coverage[i]) continue;
    bool differs = a.coverage[i] != b.coverage[i];
    for (int c = 0; c < 4 && !differs; ++c) differs = std::fabs(a.rgba[i * 4 + c] - b.rgba[i * 4 + c]) > tolerance;
    n += differs;
  }
  return n;
}

// A backend's image of `shape` drawn with an effect pass stating `states`, its pixel shader
// returning `alpha` (each backend's test supplies it).
using DrawStates = std::function<Image(const std::string& shape, const std::string& states, const std::string& alpha,
                                       int size)>;

// CCW, D3D's default, culls the back faces of GLUT's shapes under the scene's D3D camera.
inline void expect_cull_modes(const DrawStates& draw) {
  const Image none = draw("sphere", "CullMode = NONE;", "1.0", kStateImageSize);
  const Image ccw = draw("sphere", "CullMode = CCW;", "1.0", kStateImageSize);
  const Image cw = draw("sphere", "CullMode = CW;", "1.0", kStateImageSize);
  ASSERT_GT(covered(none), 300);
  EXPECT_EQ(differing_pixels(none, ccw), 0) << "D3D's default CullMode must only remove hidden faces";
  EXPECT_GT(differing_pixels(none, cw), covered(none) / 2) << "CW culls the visible faces: the inside shows";
}

inline void expect_wireframe_covers_fewer_pixels(const DrawStates& draw) {
  // Large enough that the low-tessellation torus's edges are far apart.
  const Image solid = draw("torus", "FillMode = SOLID;", "1.0", 128);
  const Image wire = draw("torus", "FillMode = WIREFRAME;", "1.0", 128);
  ASSERT_GT(covered(solid), 1000);
  EXPECT_GT(covered(wire), 0);
  EXPECT_LT(covered(wire), covered(solid) * 9 / 10) << covered(wire) << " of " << covered(solid);
}

inline void expect_depth_states_change_the_torus(const DrawStates& draw) {
  const Image depth = draw("torus", "CullMode = NONE; ZEnable = TRUE;", "1.0", kStateImageSize);
  const Image no_test = draw("torus", "CullMode = NONE; ZEnable = FALSE;", "1.0", kStateImageSize);
  const Image no_write = draw("torus", "CullMode = NONE; ZWriteEnable = FALSE;", "1.0", kStateImageSize);
  EXPECT_GT(differing_pixels(depth, no_test), 20);
  // One draw into a cleared buffer: without writes every fragment passes, as without the test.
  EXPECT_EQ(differing_pixels(no_test, no_write), 0);
  EXPECT_EQ(covered(depth), covered(no_test)) << "coverage is still read from depth";
}

inline void expect_alpha_blending_with_the_cleared_target(const DrawStates& draw) {
  const Image opaque = draw("sphere", "AlphaBlendEnable = FALSE;", "0.5", kStateImageSize);
  const Image blended =
      draw("sphere", "AlphaBlendEnable = TRUE; SrcBlend = SRCALPHA; DestBlend = INVSRCALPHA;", "0.5", kStateImageSize);
  ASSERT_EQ(covered(opaque), covered(blended));
  int checked = 0;
  for (size_t i = 0; i < opaque.coverage.size(); ++i) {
    if (!opaque.coverage[i]) continue;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(blended.rgba[i * 4 + c], 0.5f * opaque.rgba[i * 4 + c], 1e-5f) << i;
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

// u = 1.25 on a red-green 2x1 texture: WRAP reads red, CLAMP and MIRROR green, BORDER white.
inline void expect_sampler_address_modes(Backend& backend, std::initializer_list<ShaderPath> paths) {
  const std::pair<const char*, std::array<float, 4>> expected[] = {
      {"WRAP", {1, 0, 0, 1}}, {"CLAMP", {0, 1, 0, 1}}, {"MIRROR", {0, 1, 0, 1}}, {"BORDER", {1, 1, 1, 1}}};
  for (ShaderPath path : paths) {
    for (const auto& [mode, rgba] : expected) {
      auto colour = sampled_colour(backend, path, mode);
      ASSERT_TRUE(colour) << mode << ": " << colour.error().to_string();
      for (int c = 0; c < 4; ++c)
        EXPECT_EQ((*colour)[c], rgba[c]) << to_string(path) << " AddressU = " << mode << ", channel " << c;
    }
  }
}

}  // namespace shaderbed::test
