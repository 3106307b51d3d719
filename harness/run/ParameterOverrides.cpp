#include "run/ParameterOverrides.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

namespace shaderbed {

Result<std::pair<std::string, std::vector<double>>> parse_parameter(const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    return fail(ErrorStage::options, fmt::format("--param '{}' is not name=value[,value...]", text));
  std::vector<double> values;
  const std::string list = text.substr(eq + 1);
  size_t start = 0;
  while (start <= list.size()) {
    const size_t comma = std::min(list.find(',', start), list.size());
    const std::string item = list.substr(start, comma - start);
    double v = 0;
    auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), v);
    if (item.empty() || ec != std::errc() || end != item.data() + item.size())
      return fail(ErrorStage::options, fmt::format("--param '{}': '{}' is not a number", text, item));
    // NaN would make the render and the reference both NaN, and NaN compares as no error.
    if (!std::isfinite(v)) return fail(ErrorStage::options, fmt::format("--param '{}': '{}' is not a finite number", text, item));
    values.push_back(v);
    start = comma + 1;
  }
  return std::pair{text.substr(0, eq), values};
}

Result<void> apply_parameter_overrides(const std::vector<std::string>& overrides, const std::vector<std::string>& selected,
                                       std::vector<Case>& cases) {
  for (const std::string& text : overrides) {
    auto parsed = parse_parameter(text);
    if (!parsed) return std::unexpected(parsed.error());
    const auto& [name, values] = *parsed;
    int applied = 0;
    for (Case& c : cases) {
      // A case is selected by name, or by its file (`--case ~/port/phong.toml`).
      const bool chosen = selected.empty() || std::ranges::any_of(selected, [&](const std::string& s) {
        return s == c.name || (s.ends_with(".toml") && std::filesystem::path(s).stem() == c.name);
      });
      if (!chosen) continue;
      auto it = c.params.find(name);
      if (it == c.params.end()) continue;
      if (it->second.size() != values.size())
        return fail(ErrorStage::options, fmt::format("--param {}: case '{}' expects {} value(s), got {}", name, c.name,
                                           it->second.size(), values.size()));
      it->second = values;
      ++applied;
    }
    if (applied == 0) return fail(ErrorStage::options, fmt::format("--param {}: no selected case has a parameter '{}'", name, name));
  }
  return {};
}

}  // namespace shaderbed
