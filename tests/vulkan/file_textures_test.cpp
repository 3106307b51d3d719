// File-style textures on lavapipe: RGBA8, sRGB and float texels, every sampler setting
// (nearest/linear, wrap/clamp/mirror/border, mip levels), cube maps, and HLSL SM5's
// Texture2D + SamplerState as separate descriptors whose pairing the reflection records.
#include <gtest/gtest.h>

#include <algorithm>

#include "FileTextureProbes.h"
#include "compile/CrossGlsl.h"
#include "VulkanTestSupport.h"

namespace shaderbed::vulkan_test {
namespace {

using namespace file_texture_probes;

Result<std::vector<Rgba>> sample_file(const CompiledProgram& program, const TextureResolver& textures,
                                 const std::vector<Probe>& probes) {
  const MapResolver uniforms({{"coords", probe_coords(probes)}});
  auto out = draw_textured(program, full_screen_quad(), uniforms, &textures, int(probes.size()), 1);
  if (!out) return std::unexpected(out.error());
  return probe_values(out->image, int(probes.size()));
}

const CompiledProgram& glsl_program(bool cube = false) {
  static Result<CompiledProgram> flat = compile_glsl(passthrough_vertex_shader, glsl_probe(false));
  static Result<CompiledProgram> cubic = compile_glsl(passthrough_vertex_shader, glsl_probe(true));
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

TEST(VulkanFileTexture, NearestAndLinearFiltering) { EXPECT_TRUE(check_filters(sample_file, glsl_program(), "tex", "tex")); }
TEST(VulkanFileTexture, WrapClampMirrorBorder) { EXPECT_TRUE(check_address_modes(sample_file, glsl_program(), "tex", "tex")); }
TEST(VulkanFileTexture, SrgbIsDecodedWhenSampled) { EXPECT_TRUE(check_srgb(sample_file, glsl_program(), "tex")); }
TEST(VulkanFileTexture, MipLevelsAndMipFilter) { EXPECT_TRUE(check_mip_levels(sample_file, glsl_program(), "tex", "tex")); }
TEST(VulkanFileTexture, CubeMapFaces) { EXPECT_TRUE(check_cube(sample_file, glsl_program(true), "tex")); }

TEST(VulkanFileTexture, Sm5TextureAndSamplerStateAreSeparateDescriptors) {
  const Reflection& r = hlsl_program().fragment.reflection;
  ASSERT_EQ(r.samplers.size(), 2u);
  const auto find = [&](const std::string& name) {
    return std::ranges::find(r.samplers, name, &SamplerBinding::name);
  };
  ASSERT_NE(find("probeTexture"), r.samplers.end());
  ASSERT_NE(find("probeSampler"), r.samplers.end());
  EXPECT_EQ(find("probeTexture")->kind, SamplerKind::image);
  EXPECT_EQ(find("probeSampler")->kind, SamplerKind::sampler);
  EXPECT_EQ(find("probeTexture")->paired, std::vector<std::string>{"probeSampler"});
  EXPECT_EQ(find("probeSampler")->paired, std::vector<std::string>{"probeTexture"});
}

// SPIRV-Cross needs the pair combined for GLSL (otherwise "Cannot find mapping for
// combined sampler"): the Vulkan-target SPIR-V with its separate image and sampler
// cross-compiles to one sampler2D.
TEST(VulkanFileTexture, SpirvCrossCombinesTheSm5Pair) {
  auto glsl = spirv_to_glsl(hlsl_program().fragment.spirv, Stage::fragment);
  ASSERT_TRUE(glsl) << glsl.error().to_string();
  EXPECT_NE(glsl->find("uniform sampler2D"), std::string::npos) << *glsl;
  EXPECT_EQ(glsl->find("uniform texture2D"), std::string::npos) << *glsl;
}

// The texels come from the Texture2D's texture, the filtering and addressing from the
// SamplerState's settings: both must reach their own descriptor.
TEST(VulkanFileTexture, Sm5TextureAndSamplerStateFilter) {
  EXPECT_TRUE(check_filters(sample_file, hlsl_program(), "probeTexture", "probeSampler"));
}
TEST(VulkanFileTexture, Sm5SamplerStateAddressModes) {
  EXPECT_TRUE(check_address_modes(sample_file, hlsl_program(), "probeTexture", "probeSampler"));
}
TEST(VulkanFileTexture, Sm5MipLevels) {
  EXPECT_TRUE(check_mip_levels(sample_file, hlsl_program(), "probeTexture", "probeSampler"));
}

TEST(VulkanFileTexture, CustomBorderColourIsRefusedByName) {
  SamplerSettings s;
  s.address_u = AddressMode::border;
  s.border_color[0] = 0.5f;
  const SettingsResolver resolver({{"tex", strip()}}, {{"tex", s}});
  auto got = sample_file(glsl_program(), resolver, {{0.5f, 0.5f}});
  ASSERT_FALSE(got);
  EXPECT_NE(got.error().message.find("border colour"), std::string::npos) << got.error().to_string();
  EXPECT_NE(got.error().message.find("'tex'"), std::string::npos) << got.error().to_string();
}

TEST(VulkanFileTexture, CubeMapOnA2DSamplerIsAnErrorNamingIt) {
  std::vector<int> bytes(6 * 4, 255);
  const SettingsResolver resolver({{"tex", rgba8("sky", 1, 1, bytes, false, true)}});
  auto got = sample_file(glsl_program(), resolver, {{0.5f, 0.5f}});
  ASSERT_FALSE(got);
  EXPECT_NE(got.error().message.find("cube map"), std::string::npos) << got.error().to_string();
  EXPECT_NE(got.error().message.find("'tex'"), std::string::npos) << got.error().to_string();
}

}  // namespace
}  // namespace shaderbed::vulkan_test
