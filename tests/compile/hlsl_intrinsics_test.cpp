// The HLSL intrinsic corrections (compile/HlslIntrinsics.h) route calls, and only calls,
// to correct helpers; their values are checked on the GPU by tests/conformance.
#include <gtest/gtest.h>

#include "compile/Compiler.h"
#include "compile/HlslIntrinsics.h"

namespace shaderbed {
namespace {

TEST(HlslIntrinsics, EveryCorrectionIsDefinedForAPlainShader) {
  const std::string preamble = hlsl_intrinsic_corrections("float4 main() : SV_Target { return lit(1, 1, 2); }");
  for (const char* macro : {"#define lit(", "#define ldexp(", "#define fmod(", "#define round("})
    EXPECT_NE(preamble.find(macro), std::string::npos) << macro;
}

TEST(HlslIntrinsics, AnAuthorsOwnFunctionOfTheSameNameIsLeftAlone) {
  const std::string own = "float4 lit(float a, float b, float c) { return float4(a, b, c, 1); }\n"
                          "float4 main() : SV_Target { return lit(1, 2, 3); }\n";
  EXPECT_EQ(hlsl_intrinsic_corrections(own).find("#define lit("), std::string::npos);
  auto module = compile_stage(Language::hlsl, ShaderSource{.stage = Stage::fragment, .path = "own_lit.hlsl", .text = own},
                              Target::vulkan);
  EXPECT_TRUE(module) << module.error().to_string();
}

TEST(HlslIntrinsics, CgTakesItsOwnLitAndTheOtherCorrections) {
  const std::string preamble = hlsl_intrinsic_corrections("x", HlslIntrinsicSet{.lit = false});
  EXPECT_EQ(preamble.find("#define lit("), std::string::npos);
  EXPECT_NE(preamble.find("#define fmod("), std::string::npos);
}

TEST(HlslIntrinsics, NamesThatAreNotCallsStillCompile) {
  // A variable and a struct member called like an intrinsic: only `name(` expands.
  const std::string text = "struct S { float round; };\n"
                           "float4 main() : SV_Target { S s; s.round = 2.5; float fmod = 1.0;\n"
                           "  return float4(s.round, fmod, ldexp(1.5, 2.0), round(2.5)); }\n";
  for (Language language : {Language::hlsl, Language::cg}) {
    auto module = compile_stage(language, ShaderSource{.stage = Stage::fragment, .path = "names.hlsl", .text = text},
                                Target::vulkan);
    EXPECT_TRUE(module) << to_string(language) << ": " << module.error().to_string();
  }
}

}  // namespace
}  // namespace shaderbed
