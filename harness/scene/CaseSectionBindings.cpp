// [bindings.<language>]: each uniform's value from scene quantities, parameters and literals.
#include "scene/CaseSections.h"

#include "scene/TomlKeys.h"

namespace shaderbed::case_sections {
namespace {

// A binding's value: a name, literal numbers, or an array mixing names and numbers.
Result<std::vector<BindingSource>> binding_sources(const std::string& path, const std::string& uniform,
                                                   const toml::node& node) {
  if (auto s = node.value<std::string>()) return std::vector<BindingSource>{{*s, {}}};
  std::vector<double> numbers_only;
  if (literal_numbers(node, numbers_only)) return std::vector<BindingSource>{{"", std::move(numbers_only)}};
  const toml::array* a = node.as_array();
  if (!a)
    return std::unexpected(at(path, node, "binding of '" + uniform +
                                              "' must be a name, a number, an array of names and numbers, or "
                                              "{ value = ..., layout = \"row_vector\" }"));
  std::vector<BindingSource> sources;
  for (const toml::node& e : *a) {
    if (auto s = e.value<std::string>()) {
      sources.push_back({*s, {}});
      continue;
    }
    std::vector<double> values;
    if (!literal_numbers(e, values))
      return std::unexpected(at(path, e, "binding of '" + uniform + "' holds something that is neither a name nor a number"));
    if (sources.empty() || !sources.back().name.empty()) sources.push_back({});
    sources.back().literal.insert(sources.back().literal.end(), values.begin(), values.end());
  }
  return sources;
}

Result<Binding> binding(const std::string& path, const std::string& uniform, const toml::node& node) {
  Binding b{.line = int(node.source().begin.line)};
  const toml::node* value = &node;
  if (const toml::table* t = node.as_table()) {
    value = t->get("value");
    if (!value) return std::unexpected(at(path, node, "binding of '" + uniform + "' needs value = ..."));
    if (auto ok = check_keys(path, *t, {"value", "layout"}, "the binding of '" + uniform + "'"); !ok)
      return std::unexpected(ok.error());
    for (const auto& [key, knode] : *t) {
      if (key.str() != "layout") continue;
      const auto layout = knode.value<std::string>();
      if (layout == "row_vector") b.layout = MatrixLayout::row_vector;
      else if (layout == "column_vector") b.layout = MatrixLayout::column_vector;
      else return std::unexpected(at(path, knode, "layout must be \"row_vector\" or \"column_vector\""));
    }
  }
  auto sources = binding_sources(path, uniform, *value);
  if (!sources) return std::unexpected(sources.error());
  if (sources->empty()) return std::unexpected(at(path, node, "binding of '" + uniform + "' is empty"));
  b.sources = std::move(*sources);
  return b;
}

}  // namespace

Result<void> read_bindings(const CaseDocument& doc, Case& c) {
  const std::string& path = doc.path;
  if (const toml::table* bindings = doc.root["bindings"].as_table()) {
    for (const auto& [lname, lnode] : *bindings) {
      auto lang = parse_language(std::string(lname.str()));
      if (!lang) return std::unexpected(at(path, lnode, lang.error().message));
      const toml::table* bt = lnode.as_table();
      if (!bt) return std::unexpected(at(path, lnode, "[bindings." + std::string(lname.str()) + "] must be a table"));
      BindingTable table;
      for (const auto& [uname, unode] : *bt) {
        auto b = binding(path, std::string(uname.str()), unode);
        if (!b) return std::unexpected(b.error());
        table[std::string(uname.str())] = std::move(*b);
      }
      c.bindings[*lang] = std::move(table);
    }
  }
  return {};
}

}  // namespace shaderbed::case_sections
