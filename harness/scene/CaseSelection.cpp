#include "scene/CaseSelection.h"

#include <filesystem>

#include "scene/NameFilter.h"

namespace shaderbed {
namespace {

bool names_a_file(const std::string& entry) { return entry.ends_with(".toml"); }

}  // namespace

Result<std::vector<Case>> load_selected_cases(const std::string& directory, const std::vector<std::string>& filter) {
  // A user's own case file (`--case ~/port/phong.toml`) is read where it is; names are
  // looked up in the directory.
  std::vector<std::string> by_name;
  std::vector<Case> cases;
  for (const std::string& entry : filter) {
    if (!names_a_file(entry)) {
      by_name.push_back(entry);
      continue;
    }
    if (!std::filesystem::is_regular_file(entry))
      return std::unexpected(Error{.message = "no such case file", .file = entry, .stage = ErrorStage::case_file});
    auto c = load_case(entry);
    if (!c) return std::unexpected(c.error());
    cases.push_back(std::move(*c));
  }
  if (!filter.empty() && by_name.empty()) return cases;

  auto files = list_case_files(directory);
  if (!files) return std::unexpected(files.error());
  std::vector<std::string> names;
  for (const std::string& f : *files) names.push_back(std::filesystem::path(f).stem().string());
  if (auto ok = check_names(by_name, names, "case"); !ok) return std::unexpected(ok.error());
  for (size_t i = 0; i < files->size(); ++i) {
    if (!wanted(by_name, names[i])) continue;
    auto c = load_case((*files)[i]);
    if (!c) return std::unexpected(c.error());
    cases.push_back(std::move(*c));
  }
  return cases;
}

}  // namespace shaderbed
