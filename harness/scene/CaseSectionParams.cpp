// [params]: the lighting model's parameters, each a number or an array of numbers.
#include "scene/CaseSections.h"

namespace shaderbed::case_sections {

Result<void> read_params(const CaseDocument& doc, Case& c) {
  const std::string& path = doc.path;
  const toml::table& root = doc.root;
  if (root.get("params") && !root["params"].as_table())
    return std::unexpected(at(path, *root.get("params"), "'params' must be a table: [params] name = value"));
  if (const toml::table* params = root["params"].as_table()) {
    for (const auto& [key, node] : *params) {
      auto v = numbers(path, node, std::string(key.str()));
      if (!v) return std::unexpected(v.error());
      c.params[std::string(key.str())] = *v;
    }
  }
  return {};
}

}  // namespace shaderbed::case_sections
