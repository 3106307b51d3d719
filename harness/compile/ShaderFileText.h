#pragma once
// The one place a shader's text is read from disk, for every language: the file a case
// names and each file it #includes. Read bounded (core/BoundedFile.h), with a leading
// UTF-8 byte order mark dropped: Visual Studio saves HLSL with one, fxc accepts it, and
// glslang would take its bytes for the first token.
#include <string>
#include <string_view>

#include "core/Error.h"

namespace shaderbed {

// `text` without a leading UTF-8 BOM (EF BB BF).
std::string_view without_utf8_bom(std::string_view text);

// The file's text, as the compilers see it; `what` names it in errors ("shader file").
Result<std::string> read_shader_text(const std::string& path, const std::string& what);

}  // namespace shaderbed
