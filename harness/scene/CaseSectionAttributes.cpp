// [attributes.<language>]: which mesh attribute feeds each vertex input.
#include "scene/CaseSections.h"

namespace shaderbed::case_sections {
namespace {

bool is_attribute_word(const std::string& w) {
  for (const char* known : {"position", "normal", "tangent", "binormal", "bitangent", "texcoord", "uv", "color", "colour"})
    if (w == known) return true;
  return false;
}

Result<AttributeTable> attribute_table(const std::string& path, const std::string& language, const toml::node& node) {
  const toml::table* t = node.as_table();
  if (!t) return std::unexpected(at(path, node, "[attributes." + language + "] must be a table"));
  AttributeTable table;
  for (const auto& [input, anode] : *t) {
    const std::string key(input.str());
    if (key.starts_with("location ")) {
      const std::string number = key.substr(9);
      const bool digits = !number.empty() && number.find_first_not_of("0123456789") == std::string::npos;
      if (!digits) return std::unexpected(at(path, anode, "'" + key + "': write a location as \"location N\""));
    }
    const auto word = anode.value<std::string>();
    if (!word || !is_attribute_word(*word))
      return std::unexpected(at(path, anode, "vertex input '" + key +
                                                 "' must map to position, normal, tangent, binormal (bitangent), texcoord (uv) or color"));
    table[key] = *word;
  }
  return table;
}

}  // namespace

Result<void> read_attributes(const CaseDocument& doc, Case& c) {
  const std::string& path = doc.path;
  if (const toml::node* attributes = doc.root.get("attributes")) {
    const toml::table* at_table = attributes->as_table();
    if (!at_table) return std::unexpected(at(path, *attributes, "[attributes.<language>] must be tables"));
    for (const auto& [lname, lnode] : *at_table) {
      auto lang = parse_language(std::string(lname.str()));
      if (!lang) return std::unexpected(at(path, lnode, lang.error().message));
      auto table = attribute_table(path, std::string(lname.str()), lnode);
      if (!table) return std::unexpected(table.error());
      c.attributes[*lang] = std::move(*table);
    }
  }
  return {};
}

}  // namespace shaderbed::case_sections
