// A cell whose path does not apply to the shader is "skipped": counted apart in every
// report, never a failure, its reason shown, and kept through a JSON round trip.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "report/ConsoleProblems.h"
#include "report/JsonReport.h"
#include "report/JunitReport.h"
#include "report/SummaryMatrix.h"

namespace shaderbed {
namespace {

const char* kReason = "gl[gl/glsl]: Vulkan-only GLSL (layout(set = ...) at line 4): the native GL path compiles GLSL for OpenGL";

RunReport report_with_a_skip() {
  RunReport report;
  for (const char* shape : {"sphere", "cube"})
    for (const bool skipped : {false, true}) {
      CellResult r;
      r.case_name = "c";
      r.variant = "pixel";
      r.language = "glsl";
      r.backend = skipped ? "gl" : "vulkan";
      r.path = skipped ? "glsl" : "spirv";
      r.shape = shape;
      r.status = skipped ? CellStatus::skipped : CellStatus::pass;
      if (skipped) r.message = kReason;
      report.results.push_back(r);
    }
  return report;
}

std::string console(const RunReport& report) {
  std::FILE* out = std::tmpfile();
  print_problems(report, out, false);
  print_totals(report, out);
  std::rewind(out);
  std::string text;
  for (int c; (c = std::fgetc(out)) != EOF;) text += char(c);
  std::fclose(out);
  return text;
}

TEST(SkippedCells, AreAcceptableAndCountedApart) {
  const RunReport report = report_with_a_skip();
  EXPECT_TRUE(report.acceptable());
  const std::string text = console(report);
  EXPECT_NE(text.find("skipped (the path does not apply to the shader):"), std::string::npos) << text;
  EXPECT_NE(text.find(kReason), std::string::npos) << text;
  EXPECT_NE(text.find("4 cells: 2 passed, 0 failed, 0 known, 0 errors, 2 skipped"), std::string::npos) << text;
  EXPECT_EQ(text.find("FAIL"), std::string::npos) << text;
  EXPECT_EQ(text.find("errors:"), std::string::npos) << "a skip is not an error\n" << text;
}

TEST(SkippedCells, SummaryMatrixSaysSkipAndLeavesThemOutOfTheCount) {
  RunReport report = report_with_a_skip();
  SummaryMatrix m = build_summary_matrix(report);
  ASSERT_EQ(m.rows.size(), 1u);
  ASSERT_EQ(m.columns.size(), 2u);
  for (size_t c = 0; c < 2; ++c) {
    const MatrixCell& cell = m.rows[0].cells[c];
    EXPECT_EQ(cell.text(), m.columns[c].backend == "gl" ? "skip" : "2/2");
    EXPECT_TRUE(cell.problems.empty());
  }
  report.results[1].status = CellStatus::pass;   // one of two shapes skipped: counted out of one
  m = build_summary_matrix(report);
  const size_t gl = m.columns[0].backend == "gl" ? 0 : 1;
  EXPECT_EQ(m.rows[0].cells[gl].text(), "1/1");
}

TEST(SkippedCells, JsonKeepsThemAndTotalsCountThem) {
  const std::string json = to_json(report_with_a_skip());
  EXPECT_NE(json.find("\"skipped\": 2"), std::string::npos) << json.substr(0, 600);
  auto back = parse_json(json, "skipped.json");
  ASSERT_TRUE(back) << back.error().to_string();
  EXPECT_EQ(back->count(CellStatus::skipped), 2u);
  EXPECT_EQ(back->results[1].message, kReason);
}

TEST(SkippedCells, JunitMarksThemSkippedWithTheReason) {
  const std::string xml = to_junit(report_with_a_skip());
  EXPECT_NE(xml.find("skipped=\"2\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("<skipped message=\"does not apply: gl[gl/glsl]: Vulkan-only GLSL"), std::string::npos) << xml;
  EXPECT_EQ(xml.find("<failure"), std::string::npos) << xml;
  EXPECT_EQ(xml.find("<error"), std::string::npos) << xml;
}

}  // namespace
}  // namespace shaderbed
