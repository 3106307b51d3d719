#include "compile/RelaxedPrecision.h"

#include <algorithm>
#include <regex>

#include <fmt/format.h>

#include "pipeline/SpirvWords.h"

namespace shaderbed {
namespace {

// float, float2..4 and Cg's half family as the min16float family; with `matrices`, the
// matrix types too. Cg keeps fp32 matrices: its dialect layer reads matrix declarations
// (mul() order, uniform hoisting) by their float spelling, and the arithmetic that
// matters is on the vectors.
std::string relaxed_type_defines(bool matrices) {
  std::string defines = "#define float min16float\n#define half min16float\n";
  for (int n = 2; n <= 4; ++n) {
    defines += fmt::format("#define float{0} min16float{0}\n#define half{0} min16float{0}\n", n);
    if (matrices)
      for (int m = 2; m <= 4; ++m)
        defines += fmt::format("#define float{0}x{1} min16float{0}x{1}\n#define half{0}x{1} min16float{0}x{1}\n", n, m);
  }
  return defines;
}

}  // namespace

Result<ShaderSource> relax_precision(Language language, ShaderSource source) {
  if (language == Language::glsl) {
    // #version must stay the first statement: the precision statement goes right after it.
    static const std::regex version(R"((^|\n)[ \t]*#[ \t]*version[^\n]*\n)");
    std::smatch m;
    if (!std::regex_search(source.text, m, version))
      return std::unexpected(Error{.message = "relaxed precision needs a #version line to put the precision statement after",
                                   .file = source.path,
                                   .stage = ErrorStage::compile});
    const size_t after = size_t(m.position(0) + m.length(0));
    const size_t line = size_t(std::count(source.text.begin(), source.text.begin() + after, '\n')) + 1;
    source.text.insert(after, fmt::format("precision mediump float;\n#line {}\n", line));
    return source;
  }
  source.text = relaxed_type_defines(language == Language::hlsl) + "#line 1\n" + source.text;
  return source;
}

// Here and not beside its caller in PortSource.cpp: that file includes SPIRV-Cross, whose
// spirv.hpp cannot share a translation unit with SpirvWords.h's spirv.hpp11.
size_t relaxed_precision_decorations(std::span<const uint32_t> spirv) {
  const uint32_t relaxed = std::to_underlying(spv::Decoration::RelaxedPrecision);
  size_t count = 0;
  for (const SpirvInstruction in : SpirvInstructions(spirv)) {
    if (in.opcode == spv::Op::OpDecorate && in.words.size() >= 3 && in.words[2] == relaxed) ++count;
    if (in.opcode == spv::Op::OpMemberDecorate && in.words.size() >= 4 && in.words[3] == relaxed) ++count;
  }
  return count;
}

}  // namespace shaderbed
