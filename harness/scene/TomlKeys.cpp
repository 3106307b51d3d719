#include "scene/TomlKeys.h"
#include "core/BoundedFile.h"

#include <algorithm>
#include <vector>

namespace shaderbed {
namespace {

size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string closest_key(std::string_view key, std::initializer_list<std::string_view> known) {
  std::string best;
  size_t best_distance = 0;
  for (std::string_view k : known) {
    const size_t d = edit_distance(key, k);
    if (best.empty() || d < best_distance) best = std::string(k), best_distance = d;
  }
  // A third of the word may differ: "tolerence" -> "tolerance", not "mode" -> "model".
  return best_distance <= std::max<size_t>(1, key.size() / 3) ? best : "";
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
