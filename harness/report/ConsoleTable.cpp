#include "report/ConsoleTable.h"

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "report/Markup.h"

namespace shaderbed {
namespace {

std::string verdict(const CellResult& r) {
  if (r.status == CellStatus::pass) return "pass";
  if (r.status == CellStatus::fail) return r.known_failure ? "known" : "FAIL";
  if (r.status == CellStatus::skipped) return "skip";
  return "ERROR";
}

// "1.234 [1.201, 1.310]": the median and its confidence interval, or "-".
std::string interval(const TimingInterval& t, int runs) {
  if (runs == 0) return "-";
  return fmt::format("{:.3f} [{:.3f}, {:.3f}]", t.median, t.low, t.high);
}

}  // namespace

void print_table(const RunReport& report, std::FILE* out, const TableOptions& options) {
  using markup::sci;
  std::vector<std::string> headers = {"case", "variant", "lang",     "backend", "path",
                                      "shape", "max err", "min pass", "rmse",    "verdict"};
  // --twin: the render against its shader's twin, and the twin against the reference.
  const bool twins = std::ranges::any_of(report.results, [](const CellResult& r) { return r.twin.has_value(); });
  if (twins)
    for (const char* h : {"vs twin", "twin vs ref"}) headers.push_back(h);
  if (options.timing)
    for (const char* h : {"draw ms (wall, median [CI])", "driver clock ms", "build ms"}) headers.push_back(h);
  std::vector<std::vector<std::string>> rows;
  for (const CellResult& r : report.results) {
    const bool measured = r.status == CellStatus::pass || r.status == CellStatus::fail;
    rows.push_back({r.case_name, r.variant, r.language, r.backend, r.path, r.shape,
                    measured ? sci(r.metrics.max_abs) : "-", measured ? sci(r.metrics.min_passing_interior) : "-",
                    measured ? sci(r.metrics.rmse) : "-", verdict(r)});
    if (twins) {
      const bool figures = r.twin && r.twin->error.empty();
      rows.back().push_back(figures ? sci(r.twin->max_abs) : "-");
      rows.back().push_back(figures && r.twin->reference_max_abs >= 0 ? sci(r.twin->reference_max_abs) : "-");
    }
    if (!options.timing) continue;
    const auto build = r.time_ms.find("build");
    rows.back().push_back(interval(r.gpu.wall, r.gpu.runs));
    rows.back().push_back(interval(r.gpu.device, r.gpu.runs));
    rows.back().push_back(r.program_cached                 ? "cached"
                          : build == r.time_ms.end() ? "-"
                                                     : fmt::format("{:.1f}", build->second));
  }
  const size_t columns = headers.size();
  std::vector<size_t> width(columns);
  for (size_t c = 0; c < columns; ++c) width[c] = headers[c].size();
  for (const auto& row : rows)
    for (size_t c = 0; c < columns; ++c) width[c] = std::max(width[c], row[c].size());
  auto print_row = [&](auto&& cell) {
    std::string line;
    for (size_t c = 0; c < columns; ++c) line += fmt::format("{:<{}}  ", cell(c), width[c]);
    while (!line.empty() && line.back() == ' ') line.pop_back();
    fmt::print(out, "{}\n", line);
  };
  print_row([&](size_t c) { return headers[c]; });
  for (const auto& row : rows) print_row([&](size_t c) { return row[c]; });

  if (options.timing && !report.results.empty())
    fmt::print(out, "\ntimes: each draw repeated after a warm-up; [CI] is the median's confidence interval "
                    "(order statistics). On llvmpipe GL_TIME_ELAPSED misses most rasteriser work: read the wall "
                    "column (docs/timing.md).\n");
}

}  // namespace shaderbed
