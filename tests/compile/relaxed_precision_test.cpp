// The precision sweep's source transform: the same shader, its floats declared relaxed,
// must come out of glslang decorated RelaxedPrecision, and compile errors must keep
// pointing at the author's lines.
#include <gtest/gtest.h>

#include "compile/Compiler.h"
#include "compile/RelaxedPrecision.h"
#include "pipeline/SpirvWords.h"

namespace shaderbed {
namespace {

// OpDecorate with decoration RelaxedPrecision.
size_t relaxed_decorations(const std::vector<uint32_t>& spirv) {
  size_t n = 0;
  for (const SpirvInstruction in : SpirvInstructions(spirv))
    if (in.opcode == spv::Op::OpDecorate && in.words.size() >= 3 &&
        in.words[2] == std::to_underlying(spv::Decoration::RelaxedPrecision))
      ++n;
  return n;
}

struct Sample {
  Language language;
  const char* text;
};

const Sample kFragments[] = {
    {Language::glsl, "#version 450\nlayout(location = 0) in vec3 n;\nlayout(location = 0) out vec4 c;\n"
                     "void main() { c = vec4(normalize(n) * 2.0, 1.0); }\n"},
    {Language::hlsl, "float4 main(float3 n : TEXCOORD0) : COLOR0 { return float4(normalize(n) * 2.0, 1.0); }\n"},
    {Language::cg, "void main(float3 n : TEXCOORD0, out half4 c : COLOR) { c = half4(normalize(n) * 2.0, 1.0); }\n"},
};

TEST(RelaxedPrecision, DecoratesTheArithmeticInEveryLanguage) {
  for (const Sample& s : kFragments) {
    const ShaderSource source{.stage = Stage::fragment, .path = "t.frag", .text = s.text};
    auto plain = compile_stage(s.language, source, Target::vulkan);
    ASSERT_TRUE(plain) << to_string(s.language) << ": " << plain.error().to_string();
    auto relaxed_source = relax_precision(s.language, source);
    ASSERT_TRUE(relaxed_source) << relaxed_source.error().to_string();
    auto relaxed = compile_stage(s.language, *relaxed_source, Target::vulkan);
    ASSERT_TRUE(relaxed) << to_string(s.language) << ": " << relaxed.error().to_string();
    EXPECT_EQ(relaxed_decorations(plain->spirv), 0u) << to_string(s.language);
    EXPECT_GT(relaxed_decorations(relaxed->spirv), 0u) << to_string(s.language);
  }
}

TEST(RelaxedPrecision, ErrorsKeepTheAuthorsLineNumbers) {
  const Sample broken[] = {
      {Language::glsl, "#version 450\nlayout(location = 0) out vec4 c;\nvoid main() {\n  c = vec4(1.0) +;\n}\n"},
      {Language::hlsl, "float4 main() : COLOR0\n{\n  return float4(1, 1, 1, 1) +;\n}\n"},
  };
  for (const Sample& s : broken) {
    const ShaderSource source{.stage = Stage::fragment, .path = "t.frag", .text = s.text};
    auto plain = compile_stage(s.language, source, Target::vulkan);
    ASSERT_FALSE(plain);
    auto relaxed = compile_stage(s.language, *relax_precision(s.language, source), Target::vulkan);
    ASSERT_FALSE(relaxed);
    EXPECT_GT(plain.error().line, 0) << plain.error().to_string();
    EXPECT_EQ(relaxed.error().line, plain.error().line) << relaxed.error().to_string();
  }
}

TEST(RelaxedPrecision, GlslWithoutVersionIsAClearError) {
  auto out = relax_precision(Language::glsl, {.stage = Stage::fragment, .path = "x.frag", .text = "void main() {}\n"});
  ASSERT_FALSE(out);
  EXPECT_EQ(out.error().file, "x.frag");
  EXPECT_NE(out.error().message.find("#version"), std::string::npos);
}

}  // namespace
}  // namespace shaderbed
