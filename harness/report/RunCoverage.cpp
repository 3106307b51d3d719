#include "report/RunCoverage.h"

#include <algorithm>
#include <map>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace shaderbed {

RunCoverage run_coverage(const RunReport& report) {
  std::vector<std::string> backends, languages;   // in the order the results name them
  std::map<std::pair<std::string, std::string>, size_t> cells;
  std::set<std::string> cases;
  const auto note = [](std::vector<std::string>& list, const std::string& name) {
    if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
  };
  for (const CellResult& r : report.results) {
    note(backends, r.backend);
    note(languages, r.language);
    ++cells[{r.backend, r.language}];
    cases.insert(r.case_name);
  }
  RunCoverage coverage;
  coverage.cases = cases.size();
  for (const std::string& backend : backends) {
    std::vector<std::string> squares;
    for (const std::string& language : languages)
      if (const auto it = cells.find({backend, language}); it != cells.end())
        squares.push_back(fmt::format("{} {}", language, it->second));
      else
        coverage.holes.push_back(fmt::format("{} x {}", backend, language));
    coverage.lines.push_back(fmt::format("{}: {}", backend, fmt::join(squares, ", ")));
  }
  return coverage;
}

}  // namespace shaderbed
