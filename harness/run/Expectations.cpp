#include "run/Expectations.h"

#include <toml++/toml.h>

#include "scene/TomlKeys.h"

namespace shaderbed {
namespace {

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> parts;
  size_t start = 0;
  while (true) {
    const size_t slash = s.find('/', start);
    parts.push_back(s.substr(start, slash - start));
    if (slash == std::string::npos) return parts;
    start = slash + 1;
  }
}

// '*' matches any run of characters within one segment. Greedy with one backtrack point
// (the last '*'): O(|pattern| x |text|) at worst, where the recursive form was exponential
// in the number of stars.
bool glob(std::string_view pattern, std::string_view text) {
  size_t p = 0, t = 0;
  size_t star = std::string_view::npos, resume = 0;
  while (t < text.size()) {
    if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = t;
    } else if (p < pattern.size() && pattern[p] == text[t]) {
      ++p, ++t;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      t = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

}  // namespace

bool matches(const std::string& pattern, const std::string& cell_id) {
  const auto p = split(pattern), c = split(cell_id);
  if (p.size() != c.size()) return false;
  for (size_t i = 0; i < p.size(); ++i)
    if (!glob(p[i], c[i])) return false;
  return true;
}

Result<std::vector<KnownFailure>> load_expectations(const std::string& path) {
  auto parsed = parse_toml_file(path, ErrorStage::expectations);
  if (!parsed) return std::unexpected(parsed.error());
  const toml::table& root = *parsed;
  std::vector<KnownFailure> known;
  if (auto ok = check_keys(path, root, {"known"}, "the expectations file", ErrorStage::expectations); !ok)
    return std::unexpected(ok.error());
  const toml::array* entries = root["known"].as_array();
  if (!entries) return known;
  for (const toml::node& node : *entries) {
    const int line = int(node.source().begin.line);
    const toml::table* t = node.as_table();
    if (t) {
      if (auto ok = check_keys(path, *t, {"cells", "reason"}, "[[known]]", ErrorStage::expectations); !ok)
        return std::unexpected(ok.error());
    }
    auto cells = t ? (*t)["cells"].value<std::string>() : std::nullopt;
    auto reason = t ? (*t)["reason"].value<std::string>() : std::nullopt;
    if (!cells || split(*cells).size() != 6)
      return std::unexpected(Error{.message = "each [[known]] needs cells = \"case/variant/language/backend/path/shape\"",
                                   .file = path, .line = line, .stage = ErrorStage::expectations});
    if (!reason || reason->empty())
      return std::unexpected(
          Error{.message = "each [[known]] needs a reason", .file = path, .line = line, .stage = ErrorStage::expectations});
    known.push_back({*cells, *reason, line});
  }
  return known;
}

std::vector<std::string> apply_expectations(const std::vector<KnownFailure>& known, RunReport& report) {
  std::vector<std::string> now_passing;
  for (CellResult& r : report.results)
    for (const KnownFailure& k : known) {
      if (!matches(k.pattern, r.id())) continue;
      if (r.status == CellStatus::fail) {
        r.known_failure = true;
        r.known_reason = k.reason;
      } else if (r.status == CellStatus::pass) {
        now_passing.push_back(r.id());
      }
      break;
    }
  return now_passing;
}

}  // namespace shaderbed
