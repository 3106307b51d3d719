#include "compile/ShaderFileText.h"

#include "core/BoundedFile.h"

namespace shaderbed {

std::string_view without_utf8_bom(std::string_view text) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  return text.starts_with(kBom) ? text.substr(kBom.size()) : text;
}

Result<std::string> read_shader_text(const std::string& path, const std::string& what) {
  auto text = read_bounded_file(path, what, ErrorStage::compile);
  if (!text) return std::unexpected(text.error());
  if (const std::string_view body = without_utf8_bom(*text); body.size() != text->size()) return std::string(body);
  return text;
}

}  // namespace shaderbed
