// File-style textures on OSMesa: RGBA8, sRGB and float texels, every sampler setting
// (nearest/linear, wrap/clamp/mirror/border, mip levels) and cube maps on each GLSL path,
// and HLSL SM5's Texture2D + SamplerState on the SPIR-V and SPIRV-Cross paths, where
// the GL-target SPIR-V carries them as one sampler named after the texture.
#include <gtest/gtest.h>

#include "FileTextureProbes.h"
#include "GlTestSupport.h"

namespace shaderbed::gl_test {
namespace {

using namespace file_texture_probes;

SampleFn sample_on(ShaderPath path) {
  return [path](const CompiledProgram& program, const TextureResolver& textures,
                const std::vector<Probe>& probes) -> Result<std::vector<Rgba>> {
    auto backend = gl_backend();
    if (!backend) return std::unexpected(backend.error());
    const Mesh mesh = ndc_rectangle(-1, -1, 1, 1);
    const MapResolver uniforms({{"coords", probe_coords(probes)}});
    auto out = (*backend)->render(DrawJob{.program = program, .path = path, .mesh = mesh, .uniforms = uniforms,
                                          .width = int(probes.size()), .height = 1, .textures = &textures});
    if (!out) return std::unexpected(out.error());
    return probe_values(out->image, int(probes.size()));
  };
}

const CompiledProgram& glsl_program(bool cube = false) {
  static Result<CompiledProgram> flat = compile_glsl(kPassThroughVertex, glsl_probe(false));
  static Result<CompiledProgram> cubic = compile_glsl(kPassThroughVertex, glsl_probe(true));
  const Result<CompiledProgram>& p = cube ? cubic : flat;
  EXPECT_TRUE(p) << p.error().to_string();
  static const CompiledProgram empty;
  return p ? *p : empty;
}

const CompiledProgram& hlsl_program() {
  static Result<CompiledProgram> p = compile_hlsl_probe();
  EXPECT_TRUE(p) << p.error().to_string();
  static const CompiledProgram empty;
  return p ? *p : empty;
}

class GlFileTexture : public ::testing::TestWithParam<ShaderPath> {};

TEST_P(GlFileTexture, NearestAndLinearFiltering) {
  EXPECT_TRUE(check_filters(sample_on(GetParam()), glsl_program(), "tex", "tex"));
}
TEST_P(GlFileTexture, WrapClampMirrorBorder) {
  EXPECT_TRUE(check_address_modes(sample_on(GetParam()), glsl_program(), "tex", "tex"));
}
TEST_P(GlFileTexture, SrgbIsDecodedWhenSampled) { EXPECT_TRUE(check_srgb(sample_on(GetParam()), glsl_program(), "tex")); }
TEST_P(GlFileTexture, MipLevelsAndMipFilter) {
  EXPECT_TRUE(check_mip_levels(sample_on(GetParam()), glsl_program(), "tex", "tex"));
}
TEST_P(GlFileTexture, CubeMapFaces) {
  EXPECT_TRUE(check_cube(sample_on(GetParam()), glsl_program(true), "tex"));
}

INSTANTIATE_TEST_SUITE_P(AllGlslPaths, GlFileTexture,
                         ::testing::Values(ShaderPath::native_glsl, ShaderPath::spirv, ShaderPath::cross_glsl),
                         [](const auto& info) { return std::string(to_string(info.param)); });

class GlSm5Texture : public ::testing::TestWithParam<ShaderPath> {};

TEST_P(GlSm5Texture, GlTargetMergesTextureAndSamplerStateIntoOneSampler) {
  const Reflection& r = hlsl_program().fragment_gl.reflection;
  ASSERT_EQ(r.samplers.size(), 1u);
  EXPECT_EQ(r.samplers[0].name, "probeTexture");
  EXPECT_EQ(r.samplers[0].kind, SamplerKind::combined);
}
// On GL the merged sampler is named after the texture: its settings are asked for by
// that name (CaseTextures gives it its SamplerState's).
TEST_P(GlSm5Texture, Filtering) {
  EXPECT_TRUE(check_filters(sample_on(GetParam()), hlsl_program(), "probeTexture", "probeTexture"));
}
TEST_P(GlSm5Texture, AddressModes) {
  EXPECT_TRUE(check_address_modes(sample_on(GetParam()), hlsl_program(), "probeTexture", "probeTexture"));
}
TEST_P(GlSm5Texture, Srgb) { EXPECT_TRUE(check_srgb(sample_on(GetParam()), hlsl_program(), "probeTexture")); }
TEST_P(GlSm5Texture, MipLevels) {
  EXPECT_TRUE(check_mip_levels(sample_on(GetParam()), hlsl_program(), "probeTexture", "probeTexture"));
}

INSTANTIATE_TEST_SUITE_P(SpirvAndCross, GlSm5Texture, ::testing::Values(ShaderPath::spirv, ShaderPath::cross_glsl),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace shaderbed::gl_test
