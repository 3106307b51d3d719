// What `run` and `merge` print: by default the summary matrix (no per-cell rows), --table
// every cell's row, --quiet only what did not pass and the totals; each ends with the
// failures, errors and known failures and the totals line.
#include <cstdio>
#include <string>

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

}  // namespace
}  // namespace shaderbed
