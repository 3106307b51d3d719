#include "compile/HlslIncluder.h"
#include "compile/ShaderFileText.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <sstream>

namespace shaderbed {

glslang::TShader::Includer::IncludeResult* HlslIncluder::includeLocal(const char* header, const char* includer, size_t depth) {
  namespace fs = std::filesystem;
  if (depth > 32) return failure("#include nested more than 32 deep (an include cycle?)");
  const std::string name = resolve(header, includer);
  if (once_.contains(name)) {
    const std::string& empty = texts_.emplace_back();
    return new IncludeResult(name, empty.data(), 0, nullptr);
  }
  auto text = read_shader_text(name, "#include \"" + std::string(header) + "\"");
  if (!text)
    return failure("cannot read '" + name + "': " + text.error().message +
                   " (#include \"" + header + "\" is resolved relative to the including file" +
                   (include_dirs_.empty() ? std::string(", then the case's include_dirs, which names none)")
                                          : ", then in the case's include_dirs)"));
  read_.push_back({name, std::move(*text)});
  auto prepared = prepare(read_.back().text, name, includer);
  if (!prepared) return failure(prepared.error().message);
  if (prepared->pragma_once) once_.insert(name);
  const std::string& stored = texts_.emplace_back(std::move(prepared->text));
  return new IncludeResult(name, stored.data(), stored.size(), nullptr);
}

std::string HlslIncluder::resolve(const char* header, const char* includer) const {
  namespace fs = std::filesystem;
  const fs::path base = fs::path(includer ? includer : "").parent_path();
  const std::string local = (base / header).lexically_normal().string();
  std::error_code ec;
  if (fs::exists(local, ec)) return local;
  for (const std::string& dir : include_dirs_) {
    const std::string candidate = (fs::path(dir) / header).lexically_normal().string();
    if (fs::exists(candidate, ec)) return candidate;
  }
  return local;
}

glslang::TShader::Includer::IncludeResult* HlslIncluder::includeSystem(const char* header, const char* includer, size_t depth) {
  return includeLocal(header, includer, depth);
}

Result<HlslIncluder::Prepared> HlslIncluder::prepare(const std::string& text, const std::string&, const char*) {
  static const std::regex pragma_once(R"((^|\n)[ \t]*#[ \t]*pragma[ \t]+once\b)");
  return Prepared{text, std::regex_search(text, pragma_once)};
}

glslang::TShader::Includer::IncludeResult* HlslIncluder::failure(std::string message) {
  const std::string& stored = texts_.emplace_back(std::move(message));
  return new IncludeResult("", stored.c_str(), stored.size(), nullptr);
}

}  // namespace shaderbed
