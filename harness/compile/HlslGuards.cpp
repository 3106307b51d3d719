#include "compile/HlslGuards.h"

#include "compile/CgTokens.h"

namespace shaderbed {

Result<void> reject_glslang_crashers(const ShaderSource& source) {
  std::vector<cg::Token> tokens = cg::lex(source.text);
  cg::assign_positions(tokens, source.path);
  for (size_t i = 0; i + 1 < tokens.size(); ++i) {
    // Only a call: a variable may be called "noise".
    if (tokens[i].is_identifier() && tokens[i].is("noise") && tokens[i + 1].is("("))
      return std::unexpected(Error{.message = "noise() is not supported: it crashes glslang's HLSL front end "
                                              "(glslang 12) and has no SPIR-V equivalent",
                                   .file = tokens[i].file, .line = tokens[i].line, .stage = ErrorStage::compile});
  }
  return {};
}

}  // namespace shaderbed
