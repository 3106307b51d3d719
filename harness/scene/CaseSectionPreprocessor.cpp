// `defines` and `include_dirs`: what the front ends' preprocessors get beside the files.
// `defines = { HAS_NORMALS = "1" }` for every language, `[defines.glsl]` for one; a
// variant's `hlsl = { ..., defines = { ... } }` for its own files. `include_dirs = ["inc"]`,
// relative to the case's shader root, for #include of headers kept apart (an engine's
// include files).
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <charconv>
#include <map>

#include "scene/CaseSections.h"

namespace shaderbed::case_sections {
namespace {

using Defines = std::vector<std::pair<std::string, std::string>>;

bool identifier(const std::string& name) {
  return !name.empty() && !std::isdigit(static_cast<unsigned char>(name.front())) &&
         std::all_of(name.begin(), name.end(), [](unsigned char ch) { return std::isalnum(ch) || ch == '_'; });
}

// `later` over `earlier`: a name defined again takes the later value in its first place.
Defines merged(Defines earlier, const Defines& later) {
  for (const auto& [name, value] : later) {
    auto it = std::ranges::find(earlier, name, &std::pair<std::string, std::string>::first);
    if (it != earlier.end()) it->second = value;
    else earlier.emplace_back(name, value);
  }
  return earlier;
}

// The shortest text that reads back as `v` (0.5, 1e-05), as a macro's replacement.
std::string shortest(double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  return std::string(text, end);
}

}  // namespace

Result<Defines> define_table(const std::string& path, const toml::table& table, bool skip_languages) {
  Defines out;
  for (const auto& [key, node] : table) {
    const std::string name(key.str());
    if (skip_languages && node.is_table() && parse_language(name)) continue;
    if (!identifier(name))
      return std::unexpected(at(path, node, "define '" + name + "' is not a macro name (letters, digits, '_')"));
    std::string value;
    if (auto b = node.value_exact<bool>()) value = *b ? "1" : "0";
    else if (auto i = node.value_exact<int64_t>()) value = std::to_string(*i);
    else if (auto d = node.value_exact<double>()) value = shortest(*d);
    else if (auto s = node.value_exact<std::string>()) value = *s;
    else
      return std::unexpected(at(path, node, "define '" + name + "' must be a string, a number or a boolean" +
                                                (node.is_table() ? " (a table is a language's: [defines.hlsl], .cg, .glsl)"
                                                                 : "")));
    if (value.find_first_of("\r\n") != std::string::npos)
      return std::unexpected(at(path, node, "define '" + name + "' must be one line"));
    out.emplace_back(name, value);
  }
  return out;
}

Result<void> read_preprocessor(const CaseDocument& doc, Case& c) {
  Defines common;
  std::map<Language, Defines> per_language;
  if (const toml::node* node = doc.root.get("defines")) {
    const toml::table* table = node->as_table();
    if (!table) return std::unexpected(at(doc.path, *node, "defines must be a table: defines = { NAME = \"value\" }"));
    auto defines = define_table(doc.path, *table, true);
    if (!defines) return std::unexpected(defines.error());
    common = std::move(*defines);
    for (const auto& [key, sub] : *table) {
      auto language = parse_language(std::string(key.str()));
      if (!language || !sub.is_table()) continue;
      auto own = define_table(doc.path, *sub.as_table(), false);
      if (!own) return std::unexpected(own.error());
      per_language[*language] = std::move(*own);
    }
  }
  std::vector<std::string> include_dirs;
  if (const toml::node* node = doc.root.get("include_dirs")) {
    const toml::array* dirs = node->as_array();
    if (!dirs) return std::unexpected(at(doc.path, *node, "include_dirs must be an array of folders: [\"include\"]"));
    for (const toml::node& d : *dirs) {
      auto dir = d.value_exact<std::string>();
      if (!dir) return std::unexpected(at(doc.path, d, "include_dirs must hold folder names (strings)"));
      const std::filesystem::path absolute = (doc.shader_root / *dir).lexically_normal();
      std::error_code ec;
      if (!std::filesystem::is_directory(absolute, ec))
        return std::unexpected(at(doc.path, d, "include folder '" + absolute.string() + "' is not a folder"));
      include_dirs.push_back(absolute.string());
    }
  }
  for (Variant& v : c.variants)
    for (auto& [language, files] : v.shaders) {
      const auto own = per_language.find(language);
      files.defines = merged(merged(common, own == per_language.end() ? Defines{} : own->second), files.defines);
      files.include_dirs = include_dirs;
    }
  return {};
}

}  // namespace shaderbed::case_sections
