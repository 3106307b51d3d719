#include "compile/SourceDefines.h"

#include "compile/GlslProfile.h"

namespace shaderbed {

std::string define_lines(const std::vector<Define>& defines) {
  std::string out;
  for (const auto& [name, value] : defines) out += "#define " + name + (value.empty() ? "" : " " + value) + "\n";
  return out;
}

namespace {

// The #line directive after which the next line is numbered `next`: GLSL 3.30 and ES 3.00
// on name the next line's number, earlier versions the directive's own.
std::string line_directive(const GlslVersion& version, int next) {
  const bool names_next = version.es ? version.number >= 300 : version.number >= 330;
  return "#line " + std::to_string(names_next ? next : next - 1) + "\n";
}

}  // namespace

std::string glsl_with_defines(const std::string& text, const std::vector<Define>& defines) {
  if (defines.empty()) return text;
  const GlslVersion version = glsl_version(text);
  if (!version.declared) return define_lines(defines) + line_directive(version, 1) + text;
  // After the #version line, so that it stays the first directive.
  size_t at = 0;
  for (int line = 1; line < version.line && at != std::string::npos; ++line) at = text.find('\n', at) + 1;
  const size_t end = text.find('\n', at);
  if (end == std::string::npos) return text + "\n" + define_lines(defines);
  return text.substr(0, end + 1) + define_lines(defines) + line_directive(version, version.line + 1) +
         text.substr(end + 1);
}

}  // namespace shaderbed
