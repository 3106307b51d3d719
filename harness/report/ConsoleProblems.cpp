#include "report/ConsoleProblems.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "report/CellExplanation.h"
#include "report/FirstLine.h"

namespace shaderbed {
namespace {

std::string where(const CellResult& r) {
  return fmt::format("{} {} {} {}/{} {}", r.case_name, r.variant, r.language, r.backend, r.path, r.shape);
}

void print_images(const CellResult& r, std::FILE* out) {
  const CellArtefacts& a = r.artefacts;
  const std::string& render = a.render_png.empty() ? a.render_exr : a.render_png;
  const std::string& error = a.error_png.empty() ? a.error_exr : a.error_png;
  if (!render.empty()) fmt::print(out, "      render: {}\n", render);
  if (!error.empty()) fmt::print(out, "      error:  {}\n", error);
  if (!a.reference_png.empty()) fmt::print(out, "      ref:    {}\n", a.reference_png);
}

size_t known_failures(const RunReport& report) {
  size_t n = 0;
  for (const CellResult& r : report.results) n += r.status == CellStatus::fail && r.known_failure;
  return n;
}

// Passing cells too. A case's warning repeats on every backend, path and shape of its
// language, so each distinct one is printed once per case/variant/language with a count.
bool print_warnings(const RunReport& report, std::FILE* out, bool blank_line_first) {
  std::vector<std::pair<std::string, size_t>> lines;   // in first-seen order
  for (const CellResult& r : report.results)
    for (const std::string& w : r.warnings) {
      const std::string line = fmt::format("{} {} {}: {}", r.case_name, r.variant, r.language, w);
      auto it = std::find_if(lines.begin(), lines.end(), [&](const auto& l) { return l.first == line; });
      if (it == lines.end()) lines.emplace_back(line, 1);
      else ++it->second;
    }
  if (lines.empty()) return false;
  fmt::print(out, "{}warnings:\n", blank_line_first ? "\n" : "");
  for (const auto& [line, cells] : lines) fmt::print(out, "  {} ({} cell{})\n", line, cells, cells == 1 ? "" : "s");
  return true;
}

}  // namespace

bool print_problems(const RunReport& report, std::FILE* out, bool blank_line_first) {
  bool printed = false;
  auto section = [&](const char* title, auto&& wanted, auto&& body) {
    bool header = false;
    for (const CellResult& r : report.results) {
      if (!wanted(r)) continue;
      if (!header) fmt::print(out, "{}{}:\n", printed || blank_line_first ? "\n" : "", title);
      header = printed = true;
      body(r);
    }
  };
  section("failures", [](const CellResult& r) { return r.status == CellStatus::fail && !r.known_failure; },
          [&](const CellResult& r) {
            fmt::print(out, "  {}: {}\n", where(r), r.message.empty() ? "failed" : first_line(r.message));
            fmt::print(out, "      attribution: {}{}\n", r.attribution.empty() ? "none" : r.attribution,
                       r.attribution_reason.empty() ? "" : " - " + r.attribution_reason);
            if (const std::string best = best_explanation(r); !best.empty())
              fmt::print(out, "      explained: {}\n", best);
            else if (!r.explanations.empty())
              fmt::print(out, "      no convention explains it; closest: {}\n", r.explanations.front().summary);
            if (const std::string against = judged_against(r); !against.empty())
              fmt::print(out, "      judged against: {}\n", against);
            if (!r.reference_note.empty()) fmt::print(out, "      reference: {}\n", r.reference_note);
            print_images(r, out);
          });
  section("errors", [](const CellResult& r) { return r.status == CellStatus::error; },
          [&](const CellResult& r) { fmt::print(out, "  {}: {}\n", where(r), r.message); });
  section("known", [](const CellResult& r) { return r.status == CellStatus::fail && r.known_failure; },
          [&](const CellResult& r) {
            fmt::print(out, "  {}: {}\n", where(r), r.message.empty() ? "failed" : first_line(r.message));
            fmt::print(out, "      known: {}\n", r.known_reason.empty() ? "(no reason given)" : r.known_reason);
            if (!r.attribution.empty()) fmt::print(out, "      attribution: {}\n", r.attribution);
          });
  section("skipped (the path does not apply to the shader)", [](const CellResult& r) { return r.status == CellStatus::skipped; },
          [&](const CellResult& r) { fmt::print(out, "  {}: {}\n", where(r), r.message); });
  section("known failures that passed (remove them from the expectations)",
          [](const CellResult& r) { return r.status == CellStatus::pass && r.known_failure; },
          [&](const CellResult& r) { fmt::print(out, "  {}: {}\n", where(r), r.known_reason); });
  print_warnings(report, out, printed || blank_line_first) && (printed = true);
  return printed;
}

void print_totals(const RunReport& report, std::FILE* out) {
  const size_t known = known_failures(report);
  const size_t skipped = report.count(CellStatus::skipped);
  if (report.interruption)
    fmt::print(out, "INCOMPLETE: {}; the cells below are those it finished\n", report.interruption->reason);
  fmt::print(out, "{}{} cells: {} passed, {} failed, {} known, {} errors{} in {:.1f} s\n",
             report.interruption ? "INCOMPLETE: " : report.acceptable() ? "" : "FAIL: ", report.results.size(), report.count(CellStatus::pass),
             report.count(CellStatus::fail) - known, known, report.count(CellStatus::error),
             skipped ? fmt::format(", {} skipped", skipped) : "", report.wall_ms / 1000.0);
}

}  // namespace shaderbed
