#include "report/ConsoleTable.h"

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "report/ConsoleColour.h"
#include "report/Markup.h"

namespace shaderbed {
namespace {

std::string verdict(const CellResult& r) {
  if (r.status == CellStatus::pass) return "pass";
  if (r.status == CellStatus::fail) return r.known_failure ? "known" : "FAIL";
  if (r.status == CellStatus::skipped) return "skip";
  return "ERROR";
}

Tint tint_of(const CellResult& r) {
  if (r.status == CellStatus::pass) return Tint::pass;
  if (r.status == CellStatus::fail) return r.known_failure ? Tint::warn : Tint::fail;
  if (r.status == CellStatus::skipped) return Tint::none;
  return Tint::warn;
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
  constexpr size_t verdict_column = 9;
  // The escape codes go around the word, the padding after them, so the columns stay aligned.
  auto print_row = [&](auto&& cell, const CellResult* r) {
    std::string line;
    for (size_t c = 0; c < columns; ++c) {
      const std::string text = cell(c);
      line += (r && c == verdict_column ? tinted(text, tint_of(*r), options.colour) : text) +
              std::string(width[c] - text.size() + 2, ' ');
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    fmt::print(out, "{}\n", line);
  };
  print_row([&](size_t c) { return headers[c]; }, nullptr);
  for (size_t i = 0; i < rows.size(); ++i) print_row([&](size_t c) { return rows[i][c]; }, &report.results[i]);

  if (options.timing && !report.results.empty())
    fmt::print(out, "\ntimes: each draw repeated after a warm-up; [CI] is the median's confidence interval "
                    "(order statistics). On llvmpipe GL_TIME_ELAPSED misses most rasteriser work: read the wall "
                    "column (docs/timing.md).\n");
}

}  // namespace shaderbed
