// The readers every section of a case file shares: where an error is, names, numbers.
#include "scene/CaseSections.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

namespace shaderbed::case_sections {

Error at(const std::string& path, const toml::node& node, std::string message) {
  const auto& src = node.source();
  return Error{.message = std::move(message), .file = path, .line = int(src.begin.line),
               .column = int(src.begin.column), .stage = ErrorStage::case_file};
}

Error at(const std::string& path, std::string message) {
  return Error{.message = std::move(message), .file = path, .stage = ErrorStage::case_file};
}

Result<void> plain_name(const std::string& path, const toml::node& node, const std::string& name, const char* what) {
  const bool ok = !name.empty() && name.front() != '.' && std::all_of(name.begin(), name.end(), [](unsigned char ch) {
    return std::isalnum(ch) || ch == '_' || ch == '-' || ch == '.';
  });
  if (ok) return {};
  return std::unexpected(at(path, node, std::string(what) + " '" + name +
                                            "' must be letters, digits, '_', '-' or '.' (it names an output folder)"));
}

Result<std::vector<double>> numbers(const std::string& path, const toml::node& node, const std::string& key) {
  std::vector<double> out;
  // NaN or Inf would make the render and the reference both non-finite, which compares
  // as no error: refused, as no model documents them.
  auto finite = [&](const toml::node& n, double v) -> Result<void> {
    if (std::isfinite(v)) return {};
    return std::unexpected(at(path, n, "'" + key + "' must be finite, not " + (std::isnan(v) ? "nan" : "inf")));
  };
  // A boolean is 1 or 0, as a bool uniform takes it (`use_fog = true`).
  const auto number = [](const toml::node& n) -> std::optional<double> {
    if (auto b = n.value_exact<bool>()) return *b ? 1.0 : 0.0;
    return n.value<double>();
  };
  if (auto v = number(node)) {
    if (auto ok = finite(node, *v); !ok) return std::unexpected(ok.error());
    return std::vector<double>{*v};
  }
  if (const toml::array* a = node.as_array()) {
    for (const toml::node& e : *a) {
      auto v = number(e);
      if (!v) return std::unexpected(at(path, e, "'" + key + "' must hold numbers"));
      if (auto ok = finite(e, *v); !ok) return std::unexpected(ok.error());
      out.push_back(*v);
    }
    return out;
  }
  return std::unexpected(at(path, node, "'" + key + "' must be a number or an array of numbers"));
}

bool literal_numbers(const toml::node& node, std::vector<double>& out) {
  if (auto b = node.value_exact<bool>()) {
    out.push_back(*b ? 1.0 : 0.0);
    return true;
  }
  if (auto v = node.value<double>()) {
    out.push_back(*v);
    return true;
  }
  if (const toml::array* a = node.as_array()) {
    for (const toml::node& e : *a)
      if (!literal_numbers(e, out)) return false;
    return true;
  }
  return false;
}

}  // namespace shaderbed::case_sections
