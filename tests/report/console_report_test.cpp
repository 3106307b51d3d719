// What `run` and `merge` print: by default the summary matrix (no per-cell rows), --table
// every cell's row, --quiet only what did not pass and the totals; each ends with the
// failures, errors and known failures and the totals line.
#include <algorithm>
#include <cstdio>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "ReportTestSupport.h"
#include "report/ConsoleReport.h"

namespace shaderbed {
namespace {

std::string console_printed(const RunReport& report, const ConsoleOptions& options) {
  std::FILE* out = std::tmpfile();
  print_console_report(report, out, options);
  std::string s(size_t(std::ftell(out)), '\0');
  std::rewind(out);
  s.resize(std::fread(s.data(), 1, s.size(), out));
  std::fclose(out);
  return s;
}

// Lines of `text` that start (or end) with `part`.
size_t lines(const std::string& text, const std::string& part, bool at_start) {
  size_t n = 0, start = 0;
  while (start < text.size()) {
    const size_t end = std::min(text.find('\n', start), text.size());
    const std::string line = text.substr(start, end - start);
    n += at_start ? line.starts_with(part) : line.ends_with(part);
    start = end + 1;
  }
  return n;
}

const char* const kMatrix =
    "                   hlsl            glsl\n"
    "                   vulkan  gl      vulkan  gl     worst\n"
    "case     variant   spirv   cross   spirv   glsl   max err   of tol\n"
    "phong    pixel     -       0/1*    1/2!    1/1    2.00e-01  100x\n"
    "         vertex    0/1!    -       -       -      -         -\n"
    "lambert  pixel     -       -       2/2     -      nan       nan\n";
const char* const kTotals = "FAIL: 7 cells: 4 passed, 1 failed, 1 known, 1 errors in 2.5 s";

TEST(ConsoleReport, DefaultIsTheMatrixNotPerCellRows) {
  const std::string out = console_printed(test::matrix_report(), {});
  // One line per case/variant (the case named on its first), a column per language x
  // backend/path that ran, the row's worst error; then the legend.
  EXPECT_EQ(out.find(kMatrix), 0u) << out;
  EXPECT_NE(out.find("\nn/m: n of m shapes passed; ! a new failure or error (listed below)"), std::string::npos) << out;
  // No per-cell rows.
  EXPECT_EQ(out.find("min pass"), std::string::npos) << out;
  EXPECT_EQ(lines(out, "pass", false) + lines(out, "FAIL", false), 0u) << out;
  // Then the problems with their attribution, and the verdict last.
  EXPECT_NE(out.find("\nfailures:\n  phong pixel glsl vulkan/spirv cube: interior max error 2.00e-01 > 2.00e-03\n"
                     "      attribution: driver - only vulkan differs\n"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("\nerrors:\n  phong vertex hlsl vulkan/spirv sphere: shaders/hlsl/phong_vs.hlsl:3"), std::string::npos);
  EXPECT_NE(out.find("\nknown:\n  phong pixel hlsl gl/cross sphere: interior max error 1.00e-02 > 2.00e-03\n"
                     "      known: SPIRV-Cross drops precise\n"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("known failures that passed (remove them from the expectations):\n  lambert pixel glsl vulkan/spirv cube"),
            std::string::npos)
      << out;
  EXPECT_TRUE(out.ends_with(std::string("\n\n") + kTotals + "\n")) << out;
}

TEST(ConsoleReport, TableHasARowPerCell) {
  const RunReport report = test::matrix_report();
  const std::string out = console_printed(report, {.view = ConsoleView::table});
  EXPECT_TRUE(out.starts_with("case     variant  lang  backend  path   shape   max err   min pass  rmse      verdict\n"))
      << out;
  EXPECT_EQ(out.find("max err\nphong"), std::string::npos) << "no matrix\n" << out;
  EXPECT_EQ(lines(out, "  pass", false), 4u) << out;
  EXPECT_EQ(lines(out, "  FAIL", false), 1u) << out;
  EXPECT_EQ(lines(out, "  known", false), 1u) << out;
  EXPECT_EQ(lines(out, "  ERROR", false), 1u) << out;
  EXPECT_NE(out.find("\nfailures:\n"), std::string::npos);
  EXPECT_TRUE(out.ends_with(std::string("\n\n") + kTotals + "\n")) << out;
  // --timing shows the table, with its timing columns, even without --table.
  const std::string timed = console_printed(report, {.timing = true});
  EXPECT_NE(timed.find("draw ms (wall, median [CI])"), std::string::npos) << timed;
  EXPECT_TRUE(timed.starts_with("case ")) << timed;
}

TEST(ConsoleReport, QuietIsTheProblemsAndTheTotals) {
  const std::string out = console_printed(test::matrix_report(), {.view = ConsoleView::quiet});
  EXPECT_TRUE(out.starts_with("failures:\n  phong pixel glsl vulkan/spirv cube")) << out;
  EXPECT_EQ(out.find("worst"), std::string::npos) << "no matrix\n" << out;
  EXPECT_EQ(out.find("min pass"), std::string::npos) << "no table\n" << out;
  EXPECT_NE(out.find("\nerrors:\n"), std::string::npos) << out;
  EXPECT_NE(out.find("\nknown:\n"), std::string::npos) << out;
  EXPECT_TRUE(out.ends_with(std::string("\n\n") + kTotals + "\n")) << out;

  RunReport passing = test::matrix_report();
  passing.results = {passing.results[0], passing.results[2]};
  EXPECT_EQ(console_printed(passing, {.view = ConsoleView::quiet}), "2 cells: 2 passed, 0 failed, 0 known, 0 errors in 2.5 s\n")
      << "nothing to say but the totals";
}

// A cell of `variant` `language` on backend/path `column` and `shape` with `status`.
CellResult cell_of(const std::string& variant, const std::string& language, const std::string& column,
                   const std::string& shape, CellStatus status, const std::string& message) {
  CellResult r;
  r.case_name = "lambert";
  r.variant = variant;
  r.language = language;
  r.backend = column.substr(0, column.find('/'));
  r.path = column.substr(column.find('/') + 1);
  r.shape = shape;
  r.status = status;
  r.message = message;
  return r;
}

// The longest line of `text`, in columns (× and → are one each).
size_t widest_line(const std::string& text) {
  size_t widest = 0, width = 0;
  for (char c : text) {
    if (c == '\n') widest = std::max(widest, width), width = 0;
    else width += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }
  return std::max(widest, width);
}

// One bad binding errors alike on every path and shape: one entry with the cells it
// stands for, not twelve; a message that names its own cell (an artefact under the shape's
// folder) still groups, a different message does not, and a lone cell keeps its line.
TEST(ConsoleReport, IdenticalErrorsAreOneEntryWithTheirCells) {
  RunReport report;
  const std::string unbound =
      "cases/lambert.toml: bind: 3 uniforms cannot be bound: line 20: uniform 'LightVectr' of block '$Global' has no "
      "binding in the case (add it under [bindings.<language>]); line 21: uniform 'DiffuseColr' of block '$Global' has "
      "no binding in the case (add it under [bindings.<language>]); line 22: uniform 'Transfrm' of block '$Global' has "
      "no binding in the case (add it under [bindings.<language>])";
  for (const char* column : {"vulkan/spirv", "gl/spirv", "gl/cross"})
    for (const char* shape : {"cone", "cube", "sphere", "torus"})
      report.results.push_back(cell_of("pixel", "hlsl", column, shape, CellStatus::error, unbound));
  for (const char* shape : {"sphere", "torus"})
    report.results.push_back(cell_of("pixel", "glsl", "gl/glsl", shape, CellStatus::error,
                                     std::string("link failed; see out/lambert/pixel/") + shape +
                                         "/glsl-gl-glsl.frag.log"));
  report.results.push_back(cell_of("pixel", "glsl", "vulkan/spirv", "sphere", CellStatus::error, "draw timed out"));
  const std::string out = console_printed(report, {.view = ConsoleView::quiet});

  EXPECT_EQ(lines(out, "  lambert pixel hlsl: cases/lambert.toml: bind: 3 uniforms", true), 1u) << out;
  EXPECT_NE(out.find("\n      12 cells: vulkan/spirv, gl/spirv, gl/cross × cone, cube, sphere, torus\n"), std::string::npos)
      << out;
  EXPECT_EQ(lines(out, "  lambert pixel glsl: link failed; see out/lambert/pixel/sphere/glsl-gl-glsl.frag.log", true), 1u)
      << out;
  EXPECT_NE(out.find("\n      2 cells: gl/glsl sphere, torus\n"), std::string::npos) << out;
  EXPECT_NE(out.find("\n  lambert pixel glsl vulkan/spirv sphere: draw timed out\n"), std::string::npos) << out;
  EXPECT_EQ(lines(out, "  lambert", true), 3u) << out;
  // The long message is folded for a terminal at spaces, under the entry, every word kept.
  EXPECT_LE(widest_line(out), 100u) << out;
  const size_t from = out.find("  lambert pixel hlsl: ") + 22, to = out.find("\n      12 cells");
  ASSERT_LT(from, to) << out;
  std::string unfolded = out.substr(from, to - from);
  for (size_t at = unfolded.find("\n      "); at != std::string::npos; at = unfolded.find("\n      "))
    unfolded.replace(at, 7, " ");
  EXPECT_EQ(unfolded, unbound) << out;
}

// Failures group too when everything they print but the numbers of their own cell is the
// same, e.g. a blank render on every path; different attributions stay apart.
TEST(ConsoleReport, IdenticalFailuresGroupWithTheirAttribution) {
  RunReport report;
  for (const char* column : {"vulkan/spirv", "gl/spirv"}) {
    CellResult r = cell_of("vertex", "cg", column, "torus", CellStatus::fail, "render coverage 0 pixels (blank render)");
    r.attribution = "front end";
    r.attribution_reason = "every cg render fails";
    r.metrics.reference_covered_pixels = 900;
    report.results.push_back(r);
  }
  report.results.back().attribution = "unclear";
  const std::string out = console_printed(report, {.view = ConsoleView::quiet});
  EXPECT_EQ(lines(out, "  lambert vertex cg ", true), 2u) << out;
  report.results.back().attribution = "front end";
  const std::string grouped = console_printed(report, {.view = ConsoleView::quiet});
  EXPECT_NE(grouped.find("failures:\n  lambert vertex cg: render coverage 0 pixels (blank render)\n"
                         "      2 cells: vulkan/spirv, gl/spirv torus\n"
                         "      attribution: front end - every cg render fails\n"
                         "      no convention offered: the render is blank\n"),
            std::string::npos)
      << grouped;
}

// One bug measures differently on every shape: its cells are one entry, as in the HTML
// report, shown by the worst of them (the figures printed bound the group's); a port that
// departs at another line is another entry.
TEST(ConsoleReport, FailuresThatDifferOnlyInTheirNumbersAreOneEntryShownByTheWorst) {
  RunReport report;
  double max = 0.1;
  for (const char* shape : {"cone", "cube", "sphere", "torus"}) {
    max *= 2;
    CellResult r = cell_of("pixel", "glsl", "gl/glsl", shape, CellStatus::fail,
                           fmt::format("{} interior pixels over 1e-05 (max {})", int(max * 1000), max));
    r.metrics.max_abs = shape == std::string("sphere") ? 9.5 : max;
    r.attribution = "port";
    r.divergence = CellResult::Divergence{.kind = "found", .file = "port.frag", .line = 16, .text = "port.frag:16  r = reflect(L, n);"};
    report.results.push_back(r);
  }
  report.results.back().divergence->line = 17;
  const std::string out = console_printed(report, {.view = ConsoleView::quiet});
  EXPECT_EQ(lines(out, "  lambert pixel glsl", true), 2u) << out;
  EXPECT_NE(out.find("  lambert pixel glsl: 800 interior pixels over 1e-05 (max 0.8)\n"
                     "      3 cells: gl/glsl cone, cube, sphere\n"
                     "      figures: the worst of them, lambert pixel glsl gl/glsl sphere\n"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("  lambert pixel glsl gl/glsl torus: 1600 interior pixels"), std::string::npos) << out;
}

// A cell with NaN/Inf gets no convention fit (compare/ConventionFit.h); the console says why.
TEST(ConsoleReport, SaysWhyNoConventionIsOffered) {
  RunReport report;
  CellResult r = cell_of("pixel", "hlsl", "vulkan/spirv", "sphere", CellStatus::fail, "478 NaN/Inf pixels");
  r.metrics.nonfinite = r.metrics.nonfinite_mismatch = 478;
  r.metrics.covered_pixels = r.metrics.reference_covered_pixels = 2000;
  report.results.push_back(r);
  const std::string out = console_printed(report, {.view = ConsoleView::quiet});
  EXPECT_NE(out.find("\n      no convention offered: 478 pixels are NaN/Inf\n"), std::string::npos) << out;
  // An explanation that holds (a counterfactual with the same NaN/Inf) is shown instead.
  report.results[0].explanations.push_back(
      {"negated_light", "re-rendered with L negated", 0, 0, 100, true, "matches the reference re-rendered with L negated"});
  const std::string explained = console_printed(report, {.view = ConsoleView::quiet});
  EXPECT_EQ(explained.find("no convention offered"), std::string::npos) << explained;
  EXPECT_NE(explained.find("      explained: matches the reference re-rendered with L negated\n"), std::string::npos)
      << explained;
}

}  // namespace
}  // namespace shaderbed
