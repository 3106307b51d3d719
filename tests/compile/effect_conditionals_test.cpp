// The effect layer honours what an #if drops (compile/EffectConditionals.h), and reads
// the globals' initial values (compile/EffectFile.h): real parses of effect text.
#include <gtest/gtest.h>

#include "compile/CgTokens.h"
#include "compile/EffectConditionals.h"
#include "compile/EffectFile.h"

namespace shaderbed {
namespace {

// Which identifiers of `text` the preprocessor keeps, in order.
std::string kept(const std::string& text) {
  const std::vector<cg::Token> tokens = cg::lex(text);
  const ConditionalRegions regions = conditional_regions(tokens);
  std::string out;
  for (size_t i = 0; i < tokens.size(); ++i)
    if (tokens[i].is_identifier() && regions.active[i]) out += (out.empty() ? "" : " ") + tokens[i].text;
  return out;
}

TEST(EffectConditionals, FollowsIfElifElseWithTheFilesOwnDefines) {
  EXPECT_EQ(kept("#if 0\na\n#else\nb\n#endif\nc\n"), "b c");
  EXPECT_EQ(kept("#define SM 3\n#if SM >= 4\na\n#elif SM == 3\nb\n#else\nc\n#endif\n"), "b");
  EXPECT_EQ(kept("#ifdef D3D10\na\n#endif\n#ifndef D3D10\nb\n#endif\n"), "b");
  EXPECT_EQ(kept("#define D3D10\n#if defined(D3D10) && !defined D3D9\na\n#endif\n"), "a");
  EXPECT_EQ(kept("#define X 1\n#undef X\n#if X\na\n#endif\n"), "");
  EXPECT_EQ(kept("#if 1\n#if 0\na\n#else\nb\n#endif\n#else\nc\n#endif\n"), "b");
  EXPECT_EQ(kept("#if 0\n#define Y 1\n#endif\n#if Y\na\n#endif\n"), "");   // a dropped #define defines nothing
  EXPECT_EQ(kept("#define A (2 * 3)\n#if A % 4 == 2 ? 1 : 0\na\n#endif\n"), "a");
}

TEST(EffectConditionals, AConditionItCannotEvaluateKeepsEveryBranchWithANote) {
  const std::string text = "#define F(x) x\n#if F(1)\na\n#else\nb\n#endif\n";
  std::vector<cg::Token> tokens = cg::lex(text);
  cg::assign_positions(tokens, "t.fx");   // the lines the effect layer's messages use
  const ConditionalRegions regions = conditional_regions(tokens);
  EXPECT_EQ(kept(text), "a b");
  ASSERT_EQ(regions.notes.size(), 1u);
  EXPECT_EQ(regions.notes[0].line, 2);
  EXPECT_NE(regions.notes[0].text.find("cannot evaluate"), std::string::npos) << regions.notes[0].text;
}

constexpr const char* kSharedEffect = R"(float4 PS() : COLOR0 { return 1; }
#if FX_D3D10
RasterizerState rs { CullMode = Back; };
technique10 T { pass P { SetPixelShader(CompileShader(ps_4_0, PS())); SetRasterizerState(rs); } }
#else
technique T { pass P { PixelShader = compile ps_2_0 PS(); CullMode = NONE; } }
#endif
)";

TEST(EffectFile, StateObjectsUnderADroppedIfAreNotJudged) {
  auto effect = parse_effect(kSharedEffect, "shared.fx");
  ASSERT_TRUE(effect) << effect.error().to_string();
  ASSERT_EQ(effect->techniques.size(), 1u);
  ASSERT_EQ(effect->techniques[0].passes.size(), 1u);
  EXPECT_EQ(effect->techniques[0].line, 6);   // the D3D9 one
  EXPECT_EQ(effect->techniques[0].passes[0].states[0].value, "compile ps_2_0 PS ( )");

  // Where the #if holds, the state object is the error it always was.
  auto d3d10 = parse_effect(std::string("#define FX_D3D10 1\n") + kSharedEffect, "shared.fx");
  ASSERT_FALSE(d3d10);
  EXPECT_EQ(d3d10.error().line, 4);
  EXPECT_NE(d3d10.error().message.find("'RasterizerState' is not supported"), std::string::npos)
      << d3d10.error().message;
}

TEST(EffectFile, InitialValuesOfSettableGlobalsAreRead) {
  auto effect = parse_effect(R"(float3 g_vF0 = {0.04, 0.04, 0.04};
float g_fRoughness < float UIMin = 0; > = 0.5f;
float4 g_vTint : DIFFUSE = float4(1, 0.5, 0.25, 1);
float3 g_vGrey = 0.5;
bool g_bSpecular = true;
static const float kPi = 3.14159;
float g_fSum = 1.0 + 2.0;
float4x4 g_mWorld;
float4 PS() : COLOR0 { return 1; }
technique T { pass P { PixelShader = compile ps_2_0 PS(); } }
)",
                             "values.fx");
  ASSERT_TRUE(effect) << effect.error().to_string();
  const auto& v = effect->initial_values;
  ASSERT_TRUE(v.contains("g_vF0"));
  EXPECT_EQ(v.at("g_vF0").values, (std::vector<double>{0.04, 0.04, 0.04}));
  EXPECT_EQ(v.at("g_vF0").line, 1);
  EXPECT_EQ(v.at("g_fRoughness").values, std::vector<double>{0.5});
  EXPECT_EQ(v.at("g_vTint").values, (std::vector<double>{1, 0.5, 0.25, 1}));
  EXPECT_EQ(v.at("g_vGrey").values, (std::vector<double>{0.5, 0.5, 0.5}));
  EXPECT_EQ(v.at("g_bSpecular").values, std::vector<double>{1});
  EXPECT_FALSE(v.contains("kPi"));      // static const: not a parameter
  EXPECT_FALSE(v.contains("g_fSum"));   // an expression
  EXPECT_FALSE(v.contains("g_mWorld")); // no value
}

}  // namespace
}  // namespace shaderbed
