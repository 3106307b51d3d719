#include "scene/CaseSelection.h"

#include <filesystem>

#include "scene/NameFilter.h"

namespace shaderbed {

Result<std::vector<Case>> load_selected_cases(const std::string& directory, const std::vector<std::string>& filter) {
  auto files = list_case_files(directory);
  if (!files) return std::unexpected(files.error());
  std::vector<std::string> names;
  for (const std::string& f : *files) names.push_back(std::filesystem::path(f).stem().string());
  if (auto ok = check_names(filter, names, "case"); !ok) return std::unexpected(ok.error());
  std::vector<Case> cases;
  for (size_t i = 0; i < files->size(); ++i) {
    if (!wanted(filter, names[i])) continue;
    auto c = load_case((*files)[i]);
    if (!c) return std::unexpected(c.error());
    cases.push_back(std::move(*c));
  }
  return cases;
}

}  // namespace shaderbed
