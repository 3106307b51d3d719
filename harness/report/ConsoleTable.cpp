#include "report/ConsoleTable.h"

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "report/Markup.h"

namespace shaderbed {
namespace {

std::string verdict(const CellResult& r) {
  if (r.status == "pass") return "pass";
  if (r.status == "fail") return r.known_failure ? "known" : "FAIL";
  return "ERROR";
}

std::string where(const CellResult& r) {
  return fmt::format("{} {} {} {}/{} {}", r.case_name, r.variant, r.language, r.backend, r.path, r.shape);
}

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

void print_images(const CellResult& r, std::FILE* out) {
  const CellArtefacts& a = r.artefacts;
  const std::string& render = a.render_png.empty() ? a.render_exr : a.render_png;
  const std::string& error = a.error_png.empty() ? a.error_exr : a.error_png;
  if (!render.empty()) fmt::print(out, "      render: {}\n", render);
  if (!error.empty()) fmt::print(out, "      error:  {}\n", error);
  if (!a.reference_png.empty()) fmt::print(out, "      ref:    {}\n", a.reference_png);
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
  if (options.timing)
    for (const char* h : {"draw ms (wall, median [CI])", "driver clock ms", "build ms"}) headers.push_back(h);
  std::vector<std::vector<std::string>> rows;
  for (const CellResult& r : report.results) {
    const bool measured = r.status != "error";
    rows.push_back({r.case_name, r.variant, r.language, r.backend, r.path, r.shape,
                    measured ? sci(r.metrics.max_abs) : "-", measured ? sci(r.metrics.min_passing_interior) : "-",
                    measured ? sci(r.metrics.rmse) : "-", verdict(r)});
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

  auto section = [&](const char* title, auto&& wanted, auto&& body) {
    bool header = false;
    for (const CellResult& r : report.results) {
      if (!wanted(r)) continue;
      if (!header) fmt::print(out, "\n{}:\n", title);
      header = true;
      body(r);
    }
  };
  section("failures", [](const CellResult& r) { return r.status == "fail" && !r.known_failure; },
          [&](const CellResult& r) {
            fmt::print(out, "  {}: {}\n", where(r), r.message.empty() ? "failed" : first_line(r.message));
            fmt::print(out, "      attribution: {}{}\n", r.attribution.empty() ? "none" : r.attribution,
                       r.attribution_reason.empty() ? "" : " - " + r.attribution_reason);
            print_images(r, out);
          });
  section("errors", [](const CellResult& r) { return r.status != "pass" && r.status != "fail"; },
          [&](const CellResult& r) { fmt::print(out, "  {}: {}\n", where(r), r.message); });
  section("known", [](const CellResult& r) { return r.status == "fail" && r.known_failure; },
          [&](const CellResult& r) {
            fmt::print(out, "  {}: {}\n", where(r), r.message.empty() ? "failed" : first_line(r.message));
            fmt::print(out, "      known: {}\n", r.known_reason.empty() ? "(no reason given)" : r.known_reason);
            if (!r.attribution.empty()) fmt::print(out, "      attribution: {}\n", r.attribution);
          });
  section("known failures that passed (remove them from the expectations)",
          [](const CellResult& r) { return r.status == "pass" && r.known_failure; },
          [&](const CellResult& r) { fmt::print(out, "  {}: {}\n", where(r), r.known_reason); });

  size_t known = 0;
  for (const CellResult& r : report.results) known += r.status == "fail" && r.known_failure;
  if (options.timing && !report.results.empty())
    fmt::print(out, "\ntimes: each draw repeated after a warm-up; [CI] is the median's confidence interval "
                    "(order statistics). On llvmpipe GL_TIME_ELAPSED misses most rasteriser work: read the wall "
                    "column (docs/timing.md).\n");
  fmt::print(out, "\n{} cells: {} passed, {} failed, {} known, {} errors in {:.1f} s\n", report.results.size(),
             report.count("pass"), report.count("fail") - known, known, report.count("error"), report.wall_ms / 1000.0);
}

}  // namespace shaderbed
