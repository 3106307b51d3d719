// The DX9 effect layer (compile/EffectFile.h, EffectStates.h, EffectFrontEnd.h): techniques,
// passes, sampler states and render states are read; annotations and the other effect
// syntax are blanked with every line kept; real glslang compiles the result; every
// unsupported or missing thing is one error at its file and line.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "compile/Compiler.h"
#include "compile/EffectFile.h"
#include "compile/EffectFrontEnd.h"
#include "compile/EffectStates.h"

namespace shaderbed {
namespace {

// Line numbers matter to the tests below: keep this text's layout.
const std::string kEffect = R"(float4x4 WorldViewProj : WORLDVIEWPROJECTION < string UIWidget = "None"; >;
float3 LightDir : DIRECTION < string Space = "Object"; > = { 0, 1, 0 };
float4 Tint = { 1, 1, 1, 1 };
string Title = "test";
shared float Gain;
texture DiffuseMap < string ResourceName = "a.dds"; >;
textureCUBE EnvMap;
sampler DiffuseSampler : register(s1) = sampler_state
{
    Texture = <DiffuseMap>;
    MinFilter = POINT;
    MagFilter = LINEAR;
    MipFilter = NONE;
    AddressU = WRAP;
    AddressV = MIRROR;
    AddressW = BORDER;
    BorderColor = 0xFF00FF00;
    SRGBTexture = TRUE;
};
sampler EnvSampler = sampler_state { Texture = (EnvMap); AddressU = CLAMP; };
struct VSOut { float4 pos : POSITION; float3 n : TEXCOORD0; };
VSOut VS(float4 p : POSITION, float3 n : NORMAL, uniform float scale)
{
    VSOut o;
    o.pos = mul(WorldViewProj, p);
    o.n = n * scale;
    return o;
}
float4 PS(float3 n : TEXCOORD0, uniform bool tinted, uniform float gain = 1.0) : COLOR0
{
    float4 c = float4(saturate(dot(normalize(n), LightDir)).xxx, 1) * gain * Gain;
    return tinted ? c * Tint : c;
}
float4 PlainPS(float3 n : TEXCOORD0) : COLOR { return tex2D(DiffuseSampler, n.xy) + texCUBE(EnvSampler, n); }
technique Main < string Description = "main"; >
{
    pass P0 < int Order = 0; >
    {
        VertexShader = compile vs_2_0 VS(2.0);
        PixelShader = compile ps_2_0 PS(true);
        CullMode = CW;
        ZEnable = FALSE;
        ZWriteEnable = false;
        AlphaBlendEnable = TRUE;
        SrcBlend = SRCALPHA;
        DestBlend = D3DBLEND_INVSRCALPHA;
        FillMode = WIREFRAME;
        Lighting = FALSE;
    }
    pass P1
    {
        VertexShader = compile vs_3_0 VS(1.0);
        PixelShader = compile ps_3_0 PlainPS();
    }
}
technique FixedFunctionFallback
{
    pass { Texture[0] = <DiffuseMap>; ColorOp[0] = MODULATE; }
}
)";

int count_lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

TEST(EffectFile, ReadsTechniquesAndPassesAndKeepsEveryLine) {
  auto effect = parse_effect(kEffect, "test.fx");
  ASSERT_TRUE(effect) << effect.error().to_string();
  ASSERT_EQ(effect->techniques.size(), 2u);
  EXPECT_EQ(effect->techniques[0].name, "Main");
  EXPECT_EQ(effect->techniques[0].line, 35);
  ASSERT_EQ(effect->techniques[0].passes.size(), 2u);
  EXPECT_EQ(effect->techniques[0].passes[0].name, "P0");
  EXPECT_EQ(effect->techniques[0].passes[1].name, "P1");
  EXPECT_EQ(effect->techniques[1].passes[0].name, "");  // unnamed pass
  EXPECT_EQ(count_lines(effect->hlsl), count_lines(kEffect));
  for (const char* gone : {"technique", "sampler_state", "UIWidget", "ResourceName", "string", "shared", "texture "})
    EXPECT_EQ(effect->hlsl.find(gone), std::string::npos) << gone << " left in:\n" << effect->hlsl;
  // Semantics and initialisers on globals stay: glslang reads them, and they are uniforms.
  EXPECT_NE(effect->hlsl.find("float4x4 WorldViewProj : WORLDVIEWPROJECTION"), std::string::npos);
  EXPECT_NE(effect->hlsl.find("= { 0, 1, 0 }"), std::string::npos);
  ASSERT_EQ(effect->textures.size(), 2u);
  EXPECT_EQ(effect->textures[1].type, "textureCUBE");
}

TEST(EffectFile, SamplerStatesBecomeSettingsAndTypedSamplers) {
  auto effect = parse_effect(kEffect, "test.fx");
  ASSERT_TRUE(effect) << effect.error().to_string();
  ASSERT_EQ(effect->samplers.size(), 2u);
  const EffectSampler& s = effect->samplers[0];
  EXPECT_EQ(s.name, "DiffuseSampler");
  EXPECT_EQ(s.texture, "DiffuseMap");
  EXPECT_EQ(s.type, "sampler2D");
  EXPECT_EQ(s.settings.min_filter, TextureFilter::nearest);
  EXPECT_EQ(s.settings.mag_filter, TextureFilter::linear);
  EXPECT_EQ(s.settings.mip_filter, MipFilter::none);
  EXPECT_EQ(s.settings.address_u, AddressMode::wrap);
  EXPECT_EQ(s.settings.address_v, AddressMode::mirror);
  EXPECT_EQ(s.settings.address_w, AddressMode::border);
  EXPECT_FLOAT_EQ(s.settings.border_color[1], 1.0f);  // 0xAARRGGBB: green, opaque
  EXPECT_FLOAT_EQ(s.settings.border_color[0], 0.0f);
  EXPECT_FLOAT_EQ(s.settings.border_color[3], 1.0f);
  EXPECT_TRUE(s.settings.srgb);
  // A generic `sampler` of a textureCUBE is a samplerCUBE for glslang.
  EXPECT_EQ(effect->samplers[1].type, "samplerCUBE");
  EXPECT_EQ(effect->samplers[1].settings.address_u, AddressMode::clamp);
  EXPECT_NE(effect->hlsl.find("sampler2D DiffuseSampler : register(s1)"), std::string::npos) << effect->hlsl;
  EXPECT_NE(effect->hlsl.find("samplerCUBE EnvSampler"), std::string::npos) << effect->hlsl;
}

TEST(EffectFile, PassRenderStatesAreInterpreted) {
  auto effect = parse_effect(kEffect, "test.fx");
  ASSERT_TRUE(effect) << effect.error().to_string();
  auto states = interpret_pass(effect->techniques[0].passes[0], "test.fx");
  ASSERT_TRUE(states) << states.error().to_string();
  const RenderState& rs = states->render_state;
  EXPECT_EQ(rs.cull, CullMode::cw);
  EXPECT_FALSE(rs.depth_test);
  EXPECT_FALSE(rs.depth_write);
  EXPECT_TRUE(rs.blend);
  EXPECT_EQ(rs.src_blend, BlendFactor::src_alpha);
  EXPECT_EQ(rs.dest_blend, BlendFactor::inv_src_alpha);
  EXPECT_EQ(rs.fill, FillMode::wireframe);
  ASSERT_TRUE(states->vertex && states->pixel);
  EXPECT_EQ(states->vertex->profile, "vs_2_0");
  EXPECT_EQ(states->vertex->function, "VS");
  EXPECT_EQ(states->vertex->arguments, std::vector<std::string>{"2.0"});
  EXPECT_EQ(states->pixel->arguments, std::vector<std::string>{"true"});
  EXPECT_EQ(states->pixel->line, 40);
  // Lighting is fixed-function only: ignored, with a note saying so.
  ASSERT_FALSE(states->notes.empty());
  EXPECT_NE(states->notes.back().text.find("Lighting"), std::string::npos);
  // An unset pass keeps D3D9's defaults: CullMode CCW, depth on.
  auto p1 = interpret_pass(effect->techniques[0].passes[1], "test.fx");
  ASSERT_TRUE(p1) << p1.error().to_string();
  EXPECT_EQ(p1->render_state.cull, CullMode::ccw);
  EXPECT_TRUE(p1->render_state.depth_test);
  EXPECT_EQ(p1->pixel->shader_model, 3);
  // The fixed-function fallback technique is read, but refused only if chosen.
  auto fallback = interpret_pass(effect->techniques[1].passes[0], "test.fx");
  ASSERT_FALSE(fallback);
  EXPECT_EQ(fallback.error().line, 58);
  EXPECT_NE(fallback.error().message.find("Texture[0]"), std::string::npos) << fallback.error().message;
}

ProgramSource effect_program(const std::string& text, EffectChoice choice = {}) {
  return ProgramSource{.language = Language::hlsl,
                       .vertex = {.stage = Stage::vertex, .path = "test.fx", .text = text},
                       .fragment = {.stage = Stage::fragment, .path = "test.fx", .text = text},
                       .effect = std::move(choice)};
}

TEST(EffectFrontEnd, ThePassGivesEntriesWrappersAndStateAndGlslangCompilesIt) {
  auto program = compile_program(effect_program(kEffect), /*with_opengl=*/false);
  ASSERT_TRUE(program) << program.error().to_string();
  // Uniform arguments (`VS(2.0)`, `PS(true)`) are bound in wrapper entries.
  EXPECT_EQ(program->vertex.entry_point, "shaderbed_VS_compiled");
  EXPECT_EQ(program->fragment.entry_point, "shaderbed_PS_compiled");
  EXPECT_EQ(program->render_state.cull, CullMode::cw);
  EXPECT_EQ(program->render_state.fill, FillMode::wireframe);
  ASSERT_TRUE(program->sampler_settings.contains("DiffuseSampler"));
  EXPECT_TRUE(program->sampler_settings.at("DiffuseSampler").srgb);
  // `scale`, `tinted` and `gain` are constants now, not uniforms the case must bind.
  for (const ShaderModule* m : {&program->vertex, &program->fragment})
    for (const UniformBlock& b : m->reflection.uniform_blocks)
      for (const UniformMember& u : b.members) EXPECT_TRUE(u.name != "scale" && u.name != "tinted" && u.name != "gain");

  // Pass P1 of the same technique: no arguments, so the functions are entered directly.
  auto p1 = compile_program(effect_program(kEffect, {.technique = "Main", .pass = "P1"}), false);
  ASSERT_TRUE(p1) << p1.error().to_string();
  EXPECT_EQ(p1->vertex.entry_point, "shaderbed_VS_compiled");
  EXPECT_EQ(p1->fragment.entry_point, "PlainPS");
  EXPECT_EQ(p1->render_state.cull, CullMode::ccw);
  ASSERT_EQ(p1->fragment.reflection.samplers.size(), 2u);
}

TEST(EffectFrontEnd, Sm4TechniquesSetShadersWithCompileShader) {
  const std::string sm4 = kEffect +
                          "technique10 Modern\n{\n    pass P0\n    {\n"
                          "        SetVertexShader( CompileShader( vs_4_0, VS(3.0) ) );\n"
                          "        SetGeometryShader( NULL );\n"
                          "        SetPixelShader( CompileShader( ps_4_0, PlainPS() ) );\n    }\n}\n";
  auto program = compile_program(effect_program(sm4, {.technique = "Modern"}), false);
  ASSERT_TRUE(program) << program.error().to_string();
  EXPECT_EQ(program->vertex.entry_point, "shaderbed_VS_compiled");
  EXPECT_EQ(program->fragment.entry_point, "PlainPS");
}

TEST(EffectFrontEnd, RecognisedByExtensionOrByTechniqueBlocks) {
  EXPECT_TRUE(is_effect_file("a/b.FX", "float4 x;"));
  EXPECT_TRUE(is_effect_file("shader.hlsl", kEffect));
  EXPECT_FALSE(is_effect_file("shader.hlsl", "// a technique { is described here\nfloat4 main() : COLOR { return 0; }"));
}

// ---- errors: one, at the file and line ---------------------------------------------

Error prepare_error(const std::string& text, EffectChoice choice = {}) {
  auto p = compile_program(effect_program(text, std::move(choice)), false);
  EXPECT_FALSE(p) << "expected an error";
  return p ? Error{} : p.error();
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(EffectErrors, UnknownRenderStateNamesItAndItsLine) {
  const Error e = prepare_error(replace(kEffect, "Lighting = FALSE;", "StippledAlpha = TRUE;"));
  EXPECT_EQ(e.file, "test.fx");
  EXPECT_EQ(e.line, 48);
  EXPECT_NE(e.message.find("unknown render state 'StippledAlpha'"), std::string::npos) << e.message;
}

TEST(EffectErrors, UnsupportedValueOfAKnownStateIsAnError) {
  const Error e = prepare_error(replace(kEffect, "CullMode = CW;", "CullMode = SIDEWAYS;"));
  EXPECT_EQ(e.line, 41);
  EXPECT_NE(e.message.find("CullMode"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("SIDEWAYS"), std::string::npos) << e.message;
  // A state harmless only at its default is refused when set otherwise.
  const Error fog = prepare_error(replace(kEffect, "Lighting = FALSE;", "FogEnable = TRUE;"));
  EXPECT_EQ(fog.line, 48);
  EXPECT_NE(fog.message.find("FogEnable"), std::string::npos) << fog.message;
}

TEST(EffectErrors, UnknownSamplerStateNamesItTheSamplerAndItsLine) {
  const Error e = prepare_error(replace(kEffect, "MipFilter = NONE;", "MipFilterz = NONE;"));
  EXPECT_EQ(e.line, 13);
  EXPECT_NE(e.message.find("unknown sampler state 'MipFilterz'"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("DiffuseSampler"), std::string::npos) << e.message;
}

TEST(EffectErrors, MissingTechniqueOrPassIsReportedAtTheCaseLine) {
  const Error e = prepare_error(kEffect, {.technique = "Shiny", .named_in = "cases/x.toml", .line = 12});
  EXPECT_EQ(e.file, "cases/x.toml");
  EXPECT_EQ(e.line, 12);
  EXPECT_NE(e.message.find("no technique 'Shiny'"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("Main, FixedFunctionFallback"), std::string::npos) << e.message;
  const Error p = prepare_error(kEffect, {.technique = "Main", .pass = "P7", .named_in = "cases/x.toml", .line = 3});
  EXPECT_NE(p.message.find("no pass 'P7' in technique 'Main' (it has: P0, P1)"), std::string::npos) << p.message;
}

TEST(EffectErrors, CompileNamingAMissingFunctionIsAnErrorAtTheCompileLine) {
  const Error e = prepare_error(replace(kEffect, "compile ps_2_0 PS(true)", "compile ps_2_0 ShinyPS(true)"));
  EXPECT_EQ(e.file, "test.fx");
  EXPECT_EQ(e.line, 40);
  EXPECT_NE(e.message.find("ShinyPS"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("does not define"), std::string::npos) << e.message;
}

TEST(EffectErrors, TooManyCompileArgumentsOrAMissingOneAreErrors) {
  const Error many = prepare_error(replace(kEffect, "compile vs_2_0 VS(2.0)", "compile vs_2_0 VS(2.0, 3.0)"));
  EXPECT_EQ(many.line, 39);
  EXPECT_NE(many.message.find("1 uniform parameters"), std::string::npos) << many.message;
  const Error none = prepare_error(replace(kEffect, "compile vs_2_0 VS(2.0)", "compile vs_2_0 VS()"));
  EXPECT_EQ(none.line, 39);
  EXPECT_NE(none.message.find("uniform parameter 'scale'"), std::string::npos) << none.message;
}

TEST(EffectErrors, AWrongProfileForTheStageIsAnError) {
  const Error e = prepare_error(replace(kEffect, "compile vs_2_0 VS(2.0)", "compile ps_2_0 VS(2.0)"));
  EXPECT_EQ(e.line, 39);
  EXPECT_NE(e.message.find("ps_2_0"), std::string::npos) << e.message;
}

TEST(EffectErrors, HlslErrorsKeepTheAuthorsLines) {
  const Error e = prepare_error(replace(kEffect, "o.n = n * scale;", "o.n = n * undefined_thing;"));
  EXPECT_EQ(e.file, "test.fx");
  EXPECT_EQ(e.line, 26);
  EXPECT_NE(e.message.find("undefined_thing"), std::string::npos) << e.message;
}

TEST(EffectErrors, UnsupportedEffectConstructsAreNamed) {
  const Error shader_var = prepare_error(replace(kEffect, "string Title = \"test\";", "VertexShader vsArray = compile vs_2_0 VS(1.0);"));
  EXPECT_EQ(shader_var.line, 4);
  EXPECT_NE(shader_var.message.find("VertexShader"), std::string::npos) << shader_var.message;
  const Error assembly = prepare_error(replace(kEffect, "PixelShader = compile ps_2_0 PS(true);", "PixelShader = asm { ps_2_0 mov oC0, c0 };"));
  EXPECT_EQ(assembly.line, 40);
  EXPECT_NE(assembly.message.find("asm"), std::string::npos) << assembly.message;
  auto no_technique = parse_effect("float4 x;\n", "x.fx");
  ASSERT_FALSE(no_technique);
  EXPECT_NE(no_technique.error().message.find("no technique"), std::string::npos);
}

}  // namespace
}  // namespace shaderbed
