// Ports made by SPIRV-Cross (compile/PortSource.h): the original's names are kept, what
// the translation changes is listed, and every target compiles back through shaderbed's
// own compile stage with the uniforms a case can bind by the original's names.
#include <filesystem>

#include <gtest/gtest.h>

#include "compile/Compiler.h"
#include "compile/PortSource.h"

namespace shaderbed {
namespace {

const std::filesystem::path kRoot = SHADERBED_SOURCE_DIR;

ProgramSource program(Language language, const std::filesystem::path& vertex, const std::filesystem::path& fragment,
                      const std::string& vertex_entry = "main", const std::string& fragment_entry = "main") {
  auto vs = load_shader_source(Stage::vertex, vertex.string());
  auto fs = load_shader_source(Stage::fragment, fragment.string());
  EXPECT_TRUE(vs && fs);
  vs->entry_point = vertex_entry;
  fs->entry_point = fragment_entry;
  return ProgramSource{.language = language, .vertex = *vs, .fragment = *fs, .effect = {}};
}

ProgramSource phong_hlsl() {
  return program(Language::hlsl, kRoot / "shaders/hlsl/setup_vs.hlsl", kRoot / "shaders/hlsl/phong_ps.hlsl");
}

ProgramSource blinn_phong_glsl330() {
  return program(Language::glsl, kRoot / "tests/realworld/glsl330/blinn_phong.vert",
                 kRoot / "tests/realworld/glsl330/blinn_phong.frag");
}

PortedProgram port(const ProgramSource& source, PortRequest request) {
  auto compiled = compile_program(source, false);
  EXPECT_TRUE(compiled) << compiled.error().to_string();
  auto ported = port_program(*compiled, request);
  EXPECT_TRUE(ported) << ported.error().to_string();
  return ported ? *ported : PortedProgram{};
}

// The port through shaderbed's compile stage, both targets (the GL paths too).
CompiledProgram compile_back(const PortedProgram& ported, PortTarget target) {
  ProgramSource back{.language = language_of(target),
                     .vertex = {.stage = Stage::vertex, .path = "port" + port_file_suffix(target, Stage::vertex),
                                .text = ported.vertex.text, .entry_point = "main"},
                     .fragment = {.stage = Stage::fragment, .path = "port" + port_file_suffix(target, Stage::fragment),
                                  .text = ported.fragment.text, .entry_point = "main"},
                     .effect = {}};
  auto compiled = compile_program(back);
  EXPECT_TRUE(compiled) << compiled.error().to_string() << "\n" << ported.vertex.text << "\n" << ported.fragment.text;
  return compiled ? *compiled : CompiledProgram{};
}

std::vector<std::string> member_list(const Reflection& r) {
  std::vector<std::string> names;
  for (const UniformBlock& b : r.uniform_blocks)
    for (const UniformMember& m : b.members) names.push_back(m.name);
  return names;
}

bool has_change(const PortedProgram& p, const std::string& kind, const std::string& words) {
  for (const PortChange& c : p.changes)
    if (c.kind == kind && c.message.find(words) != std::string::npos) return true;
  return false;
}

std::string all_changes(const PortedProgram& p) {
  std::string s;
  for (const PortChange& c : p.changes) s += c.kind + ": " + c.message + "\n";
  return s;
}

TEST(PortSource, TargetsParseAndBadOnesSayWhatThereIs) {
  EXPECT_EQ(parse_port_target("glsl").value(), PortTarget::glsl);
  EXPECT_EQ(parse_port_target("glsl-gl").value(), PortTarget::glsl_gl);
  EXPECT_EQ(parse_port_target("hlsl").value(), PortTarget::hlsl);
  auto bad = parse_port_target("msl");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("glsl-gl"), std::string::npos) << bad.error().message;
}

TEST(PortSource, HlslToGlsl450KeepsTheNamesInANamedBlock) {
  const PortedProgram p = port(phong_hlsl(), {.target = PortTarget::glsl, .input_semantics = {}});
  EXPECT_NE(p.vertex.text.find("#version 450"), std::string::npos);
  EXPECT_NE(p.vertex.text.find("uniform VertexUniforms"), std::string::npos) << p.vertex.text;
  EXPECT_NE(p.vertex.text.find("in vec4 Position;"), std::string::npos) << p.vertex.text;
  EXPECT_NE(p.vertex.text.find("out vec3 InterPos;"), std::string::npos) << p.vertex.text;
  EXPECT_NE(p.fragment.text.find("in vec3 InterPos;"), std::string::npos) << p.fragment.text;
  EXPECT_NE(p.fragment.text.find("out vec4 FragColor;"), std::string::npos) << p.fragment.text;
  EXPECT_NE(p.fragment.text.find("normalize(EyePosition - InterPos)"), std::string::npos) << p.fragment.text;
  for (const std::string* text : {&p.vertex.text, &p.fragment.text}) {
    EXPECT_EQ(text->find("SbPort"), std::string::npos) << *text;
    EXPECT_EQ(text->find("_Global"), std::string::npos) << *text;
  }
  // The vertex input "Normal" and the varying "Normal" would collide: the varying gives way.
  EXPECT_NE(p.vertex.text.find("out vec3 v_Normal;"), std::string::npos) << p.vertex.text;
  EXPECT_EQ(p.vertex.input_names.at(0), "Position");
  EXPECT_EQ(p.fragment.uniform_names.at("SpecularColor"), "SpecularColor");
  EXPECT_TRUE(has_change(p, "semantics", "(SV_POSITION)")) << all_changes(p);
  EXPECT_TRUE(has_change(p, "renamed", "'InVertex.Position' -> 'Position'")) << all_changes(p);

  const CompiledProgram back = compile_back(p, PortTarget::glsl);
  EXPECT_EQ(member_list(back.vertex.reflection), std::vector<std::string>{"Transform"});
  EXPECT_EQ(member_list(back.fragment.reflection),
            (std::vector<std::string>{"LightVector", "EyePosition", "DiffuseColor", "SpecularColor"}));
  EXPECT_TRUE(back.native_glsl_skip_reason.empty()) << back.native_glsl_skip_reason;
}

TEST(PortSource, HlslToGlsl330FlattensBlocksAndTransposesRowMajorMatrices) {
  const PortedProgram p = port(phong_hlsl(), {.target = PortTarget::glsl_gl, .input_semantics = {}});
  EXPECT_NE(p.vertex.text.find("#version 330"), std::string::npos) << p.vertex.text;
  EXPECT_NE(p.vertex.text.find("uniform mat4 Transform;"), std::string::npos) << p.vertex.text;
  EXPECT_NE(p.vertex.text.find("Position * transpose(Transform)"), std::string::npos) << p.vertex.text;
  EXPECT_EQ(p.vertex.text.find("spvWorkaroundRowMajor"), std::string::npos) << p.vertex.text;
  EXPECT_NE(p.fragment.text.find("uniform vec4 SpecularColor;"), std::string::npos) << p.fragment.text;
  EXPECT_EQ(p.fragment.text.find("struct"), std::string::npos) << p.fragment.text;
  EXPECT_EQ(p.fragment.text.find("binding"), std::string::npos) << p.fragment.text;
  EXPECT_TRUE(has_change(p, "flattened", "LightVector, EyePosition, DiffuseColor, SpecularColor")) << all_changes(p);
  EXPECT_TRUE(has_change(p, "matrix", "transpose(Transform)")) << all_changes(p);

  const CompiledProgram back = compile_back(p, PortTarget::glsl_gl);
  EXPECT_EQ(member_list(back.vertex.reflection), std::vector<std::string>{"Transform"});
  EXPECT_FALSE(back.fragment_cross_glsl.empty());
}

TEST(PortSource, GlslToHlslGivesInputsTheSemanticsShaderbedPlaces) {
  const PortedProgram p = port(blinn_phong_glsl330(),
                               {.target = PortTarget::hlsl, .input_semantics = {{0, "POSITION"}, {1, "NORMAL"}}});
  EXPECT_NE(p.vertex.text.find("cbuffer VertexUniforms"), std::string::npos) << p.vertex.text;
  EXPECT_NE(p.vertex.text.find("float4x4 model"), std::string::npos) << p.vertex.text;
  EXPECT_NE(p.vertex.text.find("aPos : POSITION"), std::string::npos) << p.vertex.text;
  EXPECT_NE(p.vertex.text.find("aNormal : NORMAL"), std::string::npos) << p.vertex.text;
  EXPECT_NE(p.fragment.text.find("float shininess"), std::string::npos) << p.fragment.text;
  EXPECT_EQ(p.vertex.text.find("register("), std::string::npos) << p.vertex.text;
  EXPECT_EQ(p.fragment.text.find("SbPort"), std::string::npos) << p.fragment.text;
  EXPECT_TRUE(has_change(p, "semantics", "gets semantic POSITION")) << all_changes(p);

  const CompiledProgram back = compile_back(p, PortTarget::hlsl);
  ASSERT_EQ(back.vertex.reflection.inputs.size(), 2u);
  EXPECT_EQ(member_list(back.fragment.reflection),
            (std::vector<std::string>{"lightPos", "viewPos", "lightColor", "ambientColor", "objectColor",
                                      "specularColor", "shininess"}));
}

TEST(PortSource, Sm5TexturePairBecomesOneCombinedSamplerNamedAfterTheTexture) {
  const std::filesystem::path file = kRoot / "tests/realworld/hlsl5/textured_diffuse.hlsl";
  const PortedProgram p = port(program(Language::hlsl, file, file, "TexturedDiffuseVS", "TexturedDiffusePS"),
                               {.target = PortTarget::glsl, .input_semantics = {}});
  EXPECT_NE(p.fragment.text.find("uniform sampler2D shaderTexture;"), std::string::npos) << p.fragment.text;
  EXPECT_EQ(p.fragment.sampler_names.at("shaderTexture"), "shaderTexture");
  EXPECT_EQ(p.fragment.folded_sampler_states.at("shaderTexture"), "SampleType");
  EXPECT_NE(p.vertex.text.find("uniform MatrixBuffer"), std::string::npos) << p.vertex.text;
  EXPECT_TRUE(has_change(p, "samplers", "-> sampler2D 'shaderTexture'")) << all_changes(p);
  EXPECT_TRUE(has_change(p, "entry point", "'TexturedDiffuseVS' -> 'main'")) << all_changes(p);
  compile_back(p, PortTarget::glsl);
  compile_back(port(program(Language::hlsl, file, file, "TexturedDiffuseVS", "TexturedDiffusePS"),
                    {.target = PortTarget::glsl_gl, .input_semantics = {}}),
               PortTarget::glsl_gl);
}

TEST(PortSource, RelaxedPrecisionIsListedAsDropped) {
  ProgramSource src = phong_hlsl();
  src.fragment.text =
      "float3 DiffuseColor;\n"
      "struct PS_INPUT { float3 InterPos : TEXCOORD0; float3 Normal : TEXCOORD1; };\n"
      "float4 main(PS_INPUT In) : COLOR0 {\n"
      "  min16float3 n = (min16float3)normalize(In.Normal);\n"
      "  return float4(DiffuseColor * (float3)n, 1.0f);\n"
      "}\n";
  const PortedProgram p = port(src, {.target = PortTarget::glsl, .input_semantics = {}});
  EXPECT_TRUE(has_change(p, "precision", "RelaxedPrecision")) << all_changes(p);
}

}  // namespace
}  // namespace shaderbed
