#include "run/Expectations.h"

#include <fnmatch.h>

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

}  // namespace

// '*' matches any run of characters within one segment: fnmatch(3) with FNM_PATHNAME,
// whose matcher stays fast with many stars (the test with 40 of them), and with '?', '['
// and '\\' escaped, so a cell pattern has no other wildcard than the one documented.
bool matches(const std::string& pattern, const std::string& cell_id) {
  std::string escaped;
  for (const char c : pattern) {
    if (c == '?' || c == '[' || c == '\\') escaped += '\\';
    escaped += c;
  }
  return ::fnmatch(escaped.c_str(), cell_id.c_str(), FNM_PATHNAME) == 0;
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
