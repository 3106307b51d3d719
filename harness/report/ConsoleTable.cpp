#include "report/ConsoleTable.h"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include <fmt/format.h>

namespace shaderbed {

void print_table(const RunReport& report, std::FILE* out) {
  static const char* const headers[] = {"case", "variant", "lang", "backend", "path", "shape", "max err", "rmse", "verdict"};
  std::vector<std::array<std::string, 9>> rows;
  for (const CellResult& r : report.results) {
    const bool measured = r.status != "error";
    rows.push_back({r.case_name, r.variant, r.language, r.backend, r.path, r.shape,
                    measured ? fmt::format("{:.2e}", r.metrics.max_abs) : "-",
                    measured ? fmt::format("{:.2e}", r.metrics.rmse) : "-", r.status == "pass" ? "pass" : r.status == "fail" ? "FAIL" : "ERROR"});
  }
  std::array<size_t, 9> width{};
  for (size_t c = 0; c < 9; ++c) width[c] = std::string_view(headers[c]).size();
  for (const auto& row : rows)
    for (size_t c = 0; c < 9; ++c) width[c] = std::max(width[c], row[c].size());
  auto print_row = [&](auto&& cell) {
    std::string line;
    for (size_t c = 0; c < 9; ++c) line += fmt::format("{:<{}}  ", cell(c), width[c]);
    while (!line.empty() && line.back() == ' ') line.pop_back();
    fmt::print(out, "{}\n", line);
  };
  print_row([&](size_t c) { return std::string(headers[c]); });
  for (const auto& row : rows) print_row([&](size_t c) { return row[c]; });

  bool header = false;
  for (const CellResult& r : report.results) {
    if (r.status == "pass") continue;
    if (!header) fmt::print(out, "\nfailures:\n");
    header = true;
    fmt::print(out, "  {} {} {} {}/{} {}: {}{}\n", r.case_name, r.variant, r.language, r.backend, r.path, r.shape, r.message,
               r.artefacts.render_exr.empty() ? "" : " (" + r.artefacts.render_exr + ")");
  }
  fmt::print(out, "\n{} cells: {} passed, {} failed, {} errors in {:.1f} s\n", report.results.size(), report.count("pass"),
             report.count("fail"), report.count("error"), report.wall_ms / 1000.0);
}

}  // namespace shaderbed
