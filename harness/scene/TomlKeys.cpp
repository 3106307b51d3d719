#include "scene/TomlKeys.h"
#include "core/BoundedFile.h"
#include "core/ClosestName.h"

#include <algorithm>
#include <vector>

namespace shaderbed {

std::string closest_key(std::string_view key, std::initializer_list<std::string_view> known) {
  return closest_name(key, std::vector<std::string_view>(known));
}

Result<toml::table> parse_toml_file(const std::string& path, ErrorStage stage) {
  auto text = read_bounded_file(path, "TOML file", stage);
  if (!text) return std::unexpected(text.error());
  try {
    return toml::parse(*text, path);
  } catch (const toml::parse_error& e) {
    return std::unexpected(Error{.message = std::string(e.description()), .file = path,
                                 .line = int(e.source().begin.line), .column = int(e.source().begin.column),
                                 .stage = stage});
  }
}

Result<void> check_keys(const std::string& path, const toml::table& table, std::initializer_list<std::string_view> known,
                        const std::string& where, ErrorStage stage) {
  for (const auto& [key, node] : table) {
    const std::string_view k = key.str();
    if (std::find(known.begin(), known.end(), k) != known.end()) continue;
    std::string message = "unknown key '" + std::string(k) + "' in " + where;
    if (const std::string near = closest_key(k, known); !near.empty()) message += " (did you mean '" + near + "'?)";
    else {
      message += " (known: ";
      for (auto it = known.begin(); it != known.end(); ++it) message += (it == known.begin() ? "" : ", ") + std::string(*it);
      message += ")";
    }
    const auto& src = key.source().begin.line ? key.source() : node.source();
    return std::unexpected(Error{.message = message, .file = path, .line = int(src.begin.line),
                                 .column = int(src.begin.column), .stage = stage});
  }
  return {};
}

}  // namespace shaderbed
