// Instruction counts of tiny hand-written shaders, worked out by hand from what glslang 12
// emits (before optimisation), and the generated class table against known opcodes.
#include <gtest/gtest.h>

#include "compile/Compiler.h"
#include "compile/SpirvTools.h"
#include "stats/OpcodeClass.h"
#include "stats/SpirvCounts.h"

namespace shaderbed::stats {
namespace {

std::vector<uint32_t> compile_fragment(const std::string& text) {
  auto m = compile_stage(Language::glsl, ShaderSource{Stage::fragment, "test.frag", text}, Target::vulkan);
  EXPECT_TRUE(m.has_value()) << (m ? "" : m.error().to_string());
  return m ? m->spirv : std::vector<uint32_t>{};
}

TEST(OpcodeClass, GeneratedTableAgreesWithKnownOpcodes) {
  EXPECT_EQ(opcode_class(133), InstructionClass::arithmetic);   // OpFMul
  EXPECT_EQ(opcode_name(133), "OpFMul");
  EXPECT_EQ(opcode_class(87), InstructionClass::texture);       // OpImageSampleImplicitLod
  EXPECT_EQ(opcode_name(87), "OpImageSampleImplicitLod");
  EXPECT_EQ(opcode_class(249), InstructionClass::control);      // OpBranch
  EXPECT_EQ(opcode_class(61), InstructionClass::memory);        // OpLoad
  EXPECT_EQ(opcode_class(110), InstructionClass::conversion);   // OpConvertFToS
  EXPECT_EQ(opcode_name(110), "OpConvertFToS");
  EXPECT_EQ(opcode_class(12), InstructionClass::extended);      // OpExtInst
  EXPECT_EQ(opcode_class(164), InstructionClass::arithmetic);   // OpLogicalAnd (Relational_and_Logical)
  EXPECT_EQ(opcode_class(81), InstructionClass::other);         // OpCompositeExtract
  EXPECT_EQ(opcode_class(248), InstructionClass::none);         // OpLabel
  EXPECT_EQ(opcode_class(59), InstructionClass::none);          // OpVariable
  EXPECT_EQ(opcode_class(86), InstructionClass::none);          // OpSampledImage
  EXPECT_EQ(glsl_std_450_name(26), "Pow");
  EXPECT_EQ(glsl_std_450_name(69), "Normalize");
  EXPECT_EQ(glsl_std_450_name(17), "Acos");
}

// color = vec4(normalize(n) * s, 1.0):
//   OpLoad n, OpLoad s, OpStore color            memory 3
//   OpExtInst Normalize                          extended 1
//   OpVectorTimesScalar                          arithmetic 1
//   3 x OpCompositeExtract + OpCompositeConstruct other 4 (the vec4(vec3, 1) rebuild)
//   OpReturn                                     control 1
//   (OpFunction, OpLabel, OpFunctionEnd: not counted)          total 10
TEST(SpirvCounts, MultiplyAndNormalize) {
  auto counts = count_spirv(compile_fragment(R"(#version 450
layout(location = 0) in vec3 n;
layout(location = 1) in float s;
layout(location = 0) out vec4 color;
void main() { color = vec4(normalize(n) * s, 1.0); }
)"));
  ASSERT_TRUE(counts.has_value());
  EXPECT_EQ(counts->arithmetic, 1);
  EXPECT_EQ(counts->extended, 1);
  EXPECT_EQ(counts->memory, 3);
  EXPECT_EQ(counts->other, 4);
  EXPECT_EQ(counts->control, 1);
  EXPECT_EQ(counts->texture, 0);
  EXPECT_EQ(counts->conversion, 0);
  EXPECT_EQ(counts->total, 10);
  EXPECT_EQ(counts->extended_calls, (std::map<std::string, int>{{"Normalize", 1}}));
}

// if (int(uv.x) > 2) discard; color = texture(tex, uv):
//   OpAccessChain uv.x, OpLoad, OpLoad tex, OpLoad uv, OpStore color   memory 5
//   OpConvertFToS                                                      conversion 1
//   OpSGreaterThan                                                     arithmetic 1
//   OpBranchConditional, OpKill, OpReturn                              control 3
//   OpImageSampleImplicitLod                                           texture 1
//   (OpSelectionMerge and both OpLabels: markers, not counted)         total 11
TEST(SpirvCounts, TextureConversionAndControl) {
  auto counts = count_spirv(compile_fragment(R"(#version 450
layout(binding = 0) uniform sampler2D tex;
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
  if (int(uv.x) > 2) discard;
  color = texture(tex, uv);
}
)"));
  ASSERT_TRUE(counts.has_value());
  EXPECT_EQ(counts->memory, 5);
  EXPECT_EQ(counts->conversion, 1);
  EXPECT_EQ(counts->arithmetic, 1);
  EXPECT_EQ(counts->control, 3);
  EXPECT_EQ(counts->texture, 1);
  EXPECT_EQ(counts->extended, 0);
  EXPECT_EQ(counts->other, 0);
  EXPECT_EQ(counts->total, 11);
}

// pow(a * b, 5.0) with a, b scalars: OpFMul arithmetic 1, Pow extended 1, after -O as well.
TEST(SpirvCounts, OptimizedKeepsTheWork) {
  auto spirv = compile_fragment(R"(#version 450
layout(location = 0) in float a;
layout(location = 1) in float b;
layout(location = 0) out float color;
void main() { color = pow(a * b, 5.0); }
)");
  auto optimized = optimize_spirv(spirv, Target::vulkan, OptimizeLevel::performance);
  ASSERT_TRUE(optimized.has_value());
  for (const auto& module : {spirv, *optimized}) {
    auto counts = count_spirv(module);
    ASSERT_TRUE(counts.has_value());
    EXPECT_EQ(counts->arithmetic, 1);
    EXPECT_EQ(counts->extended_calls, (std::map<std::string, int>{{"Pow", 1}}));
    EXPECT_EQ(counts->memory, 3);   // two loads, one store
    EXPECT_EQ(counts->total, 6);    // + OpReturn
  }
}

TEST(SpirvCounts, RejectsGarbage) { EXPECT_FALSE(count_spirv({1, 2, 3}).has_value()); }

}  // namespace
}  // namespace shaderbed::stats
