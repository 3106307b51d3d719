// The SPIR-V instruction walker (harness/pipeline/SpirvWords.h) that every hand reader of
// SPIR-V words goes through: on modules the project compiles it must see exactly the
// instructions SPIRV-Tools' parser sees, and on a cut or corrupt module it must stop at the
// last whole instruction without reading past the end (each case walks a vector of exactly
// the words it has, so the sanitizer build catches a stray read).
#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <spirv-tools/libspirv.h>

#include "SourceTree.h"
#include "compile/Compiler.h"
#include "pipeline/SpirvWords.h"

namespace shaderbed {
namespace {

// One instruction as both readers report it.
struct WalkedInstruction {
  uint32_t opcode = 0;
  size_t offset = 0;
  size_t word_count = 0;
  bool operator==(const WalkedInstruction&) const = default;
};

std::ostream& operator<<(std::ostream& out, const WalkedInstruction& in) {
  return out << "{op " << in.opcode << " at " << in.offset << ", " << in.word_count << " words}";
}

std::vector<WalkedInstruction> walk(const std::vector<uint32_t>& spirv) {
  std::vector<WalkedInstruction> out;
  for (const SpirvInstruction in : SpirvInstructions(spirv)) {
    EXPECT_EQ(in.words.data(), spirv.data() + in.offset);
    out.push_back({std::to_underlying(in.opcode), in.offset, in.words.size()});
  }
  return out;
}

spv_result_t on_parsed_instruction(void* user, const spv_parsed_instruction_t* in) {
  auto& state = *static_cast<std::pair<const uint32_t*, std::vector<WalkedInstruction>>*>(user);
  state.second.push_back({in->opcode, size_t(in->words - state.first), in->num_words});
  return SPV_SUCCESS;
}

// The reference: SPIRV-Tools' own binary parser.
std::vector<WalkedInstruction> parse_with_spirv_tools(const std::vector<uint32_t>& spirv) {
  std::pair<const uint32_t*, std::vector<WalkedInstruction>> state{spirv.data(), {}};
  spv_context context = spvContextCreate(SPV_ENV_UNIVERSAL_1_6);
  const spv_result_t r =
      spvBinaryParse(context, &state, spirv.data(), spirv.size(), nullptr, on_parsed_instruction, nullptr);
  spvContextDestroy(context);
  EXPECT_EQ(r, SPV_SUCCESS);
  return state.second;
}

// Library shaders in each language, for both targets: names, decorations, strings, functions.
// `first_only`: the GLSL fragment shader for Vulkan alone.
std::vector<ShaderModule> compiled_modules(bool first_only) {
  struct Shader {
    Language language;
    Stage stage;
    const char* path;
  };
  const Shader shaders[] = {{Language::glsl, Stage::fragment, "glsl/phong.frag"},
                            {Language::glsl, Stage::vertex, "glsl/phong.vert"},
                            {Language::hlsl, Stage::fragment, "hlsl/blinn_phong_ps.hlsl"},
                            {Language::cg, Stage::fragment, "cg/phong_fp.cg"}};
  std::vector<ShaderModule> modules;
  for (const Shader& s : shaders) {
    auto source = load_shader_source(s.stage, (test::kShaders / s.path).string());
    EXPECT_TRUE(source) << source.error().to_string();
    if (!source) continue;
    for (Target target : {Target::vulkan, Target::opengl}) {
      auto module = compile_stage(s.language, *source, target);
      EXPECT_TRUE(module) << s.path << ": " << module.error().to_string();
      if (module) modules.push_back(std::move(*module));
      if (first_only) return modules;
    }
  }
  return modules;
}

const std::vector<ShaderModule>& modules() {
  static const std::vector<ShaderModule> compiled = compiled_modules(false);
  return compiled;
}

// The module the tests below cut and corrupt (empty if it did not compile).
const std::vector<uint32_t>& one_module() {
  static const std::vector<ShaderModule> first = compiled_modules(true);
  static const std::vector<uint32_t> none;
  return first.empty() ? none : first.front().spirv;
}

TEST(SpirvWords, WalksTheInstructionsSpirvToolsParses) {
  ASSERT_EQ(modules().size(), 8u);
  for (const ShaderModule& m : modules()) {
    const auto expected = parse_with_spirv_tools(m.spirv);
    ASSERT_GT(expected.size(), 20u) << m.source_file;
    EXPECT_EQ(walk(m.spirv), expected) << m.source_file;
  }
}

TEST(SpirvWords, ReadsTheEntryPointsNameAndDecorations) {
  for (const ShaderModule& m : modules()) {
    std::vector<std::string> entry_points;
    size_t locations = 0;
    for (const SpirvInstruction in : SpirvInstructions(m.spirv)) {
      if (in.opcode == spv::Op::OpEntryPoint && in.words.size() >= 4)
        entry_points.push_back(spirv_literal_string(in.words.subspan(3)));
      if (in.opcode == spv::Op::OpDecorate && in.words.size() >= 4 &&
          in.words[2] == std::to_underlying(spv::Decoration::Location))
        ++locations;
    }
    EXPECT_EQ(entry_points, std::vector<std::string>{m.entry_point}) << m.source_file;
    EXPECT_GT(locations, 0u) << m.source_file;
  }
}

TEST(SpirvWords, ATruncatedModuleEndsAtItsLastWholeInstruction) {
  const std::vector<uint32_t>& spirv = one_module();
  ASSERT_FALSE(spirv.empty());
  const auto all = parse_with_spirv_tools(spirv);
  for (size_t size = 0; size <= spirv.size(); ++size) {
    const std::vector<uint32_t> cut(spirv.begin(), spirv.begin() + std::ptrdiff_t(size));
    std::vector<WalkedInstruction> whole;
    for (const WalkedInstruction& in : all)
      if (in.offset + in.word_count <= size) whole.push_back(in);
    ASSERT_EQ(walk(cut), whole) << "cut to " << size << " words";
  }
}

TEST(SpirvWords, AZeroOrOverlongWordCountEndsTheWalk) {
  const std::vector<uint32_t>& spirv = one_module();
  ASSERT_FALSE(spirv.empty());
  ASSERT_LT(spirv.size(), size_t(spv::OpCodeMask));  // an overlong count still fits in 16 bits
  const auto all = parse_with_spirv_tools(spirv);
  for (size_t k : {size_t(0), all.size() / 2, all.size() - 1}) {
    const std::vector<WalkedInstruction> before(all.begin(), all.begin() + std::ptrdiff_t(k));
    std::vector<uint32_t> corrupt = spirv;
    corrupt[all[k].offset] &= spv::OpCodeMask;  // word count 0, opcode kept
    EXPECT_EQ(walk(corrupt), before) << "zero word count in instruction " << k;
    corrupt[all[k].offset] |= uint32_t(spirv.size() - all[k].offset + 1) << spv::WordCountShift;
    EXPECT_EQ(walk(corrupt), before) << "word count past the end in instruction " << k;
  }
}

TEST(SpirvWords, AModuleNoLongerThanItsHeaderHasNoInstructions) {
  const std::vector<uint32_t>& spirv = one_module();
  ASSERT_FALSE(spirv.empty());
  const std::vector<uint32_t> header(spirv.begin(), spirv.begin() + kSpirvHeaderWords);
  EXPECT_TRUE(walk(header).empty());
  EXPECT_TRUE(walk({}).empty());
}

TEST(SpirvWords, ALiteralStringEndsAtItsNulOrItsLastWord) {
  // "main" fills one word; its nul is the next word.
  EXPECT_EQ(spirv_literal_string(std::vector<uint32_t>{0x6e69616du, 0u}), "main");
  EXPECT_EQ(spirv_literal_string(std::vector<uint32_t>{0x6e69616du}), "main");  // malformed: no nul
  EXPECT_EQ(spirv_literal_string(std::vector<uint32_t>{0x00636261u, 0x64646464u}), "abc");
  EXPECT_EQ(spirv_literal_string(std::vector<uint32_t>{}), "");
}

}  // namespace
}  // namespace shaderbed
