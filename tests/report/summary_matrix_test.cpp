// The summary matrix: one row per case/variant, one column per language x backend/path that
// some cell has, pass counts per matrix cell, the row's worst error and its problem cells.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ReportTestSupport.h"
#include "report/SummaryMatrix.h"

namespace shaderbed {
namespace {

std::vector<std::string> labels(const SummaryMatrix& m) {
  std::vector<std::string> out;
  for (const MatrixColumn& c : m.columns) out.push_back(c.label());
  return out;
}

TEST(SummaryMatrix, ColumnsOnlyWhereACellExistsInTheUsualOrder) {
  const SummaryMatrix m = build_summary_matrix(test::matrix_report());
  // hlsl before glsl, vulkan before gl, the GL paths glsl, spirv, cross; no cg, no gl/spirv.
  EXPECT_EQ(labels(m), (std::vector<std::string>{"hlsl vulkan/spirv", "hlsl gl/cross", "glsl vulkan/spirv", "glsl gl/glsl"}));
  RunReport odd;
  for (const char* path : {"zeta", "cross", "alpha", "glsl"})
    odd.results.push_back({.case_name = "c", .variant = "v", .language = "glsl", .backend = "gl", .path = path, .shape = "s",
                           .status = CellStatus::pass});
  EXPECT_EQ(labels(build_summary_matrix(odd)),
            (std::vector<std::string>{"glsl gl/glsl", "glsl gl/cross", "glsl gl/alpha", "glsl gl/zeta"}))
      << "unknown paths after the known ones, by name";
  EXPECT_TRUE(build_summary_matrix(RunReport{}).rows.empty());
}

TEST(SummaryMatrix, CountsPerCaseVariantAndColumn) {
  const RunReport report = test::matrix_report();
  const SummaryMatrix m = build_summary_matrix(report);
  ASSERT_EQ(m.rows.size(), 3u);
  EXPECT_EQ(m.rows[0].case_name + "/" + m.rows[0].variant, "phong/pixel");
  EXPECT_EQ(m.rows[1].case_name + "/" + m.rows[1].variant, "phong/vertex");
  EXPECT_EQ(m.rows[2].case_name + "/" + m.rows[2].variant, "lambert/pixel");
  for (const MatrixRow& row : m.rows) ASSERT_EQ(row.cells.size(), m.columns.size());

  const MatrixRow& phong = m.rows[0];   // columns: hlsl vulkan, hlsl gl/cross, glsl vulkan, glsl gl/glsl
  EXPECT_TRUE(phong.cells[0].empty());
  EXPECT_EQ(phong.cells[0].text(), "");
  EXPECT_EQ(phong.cells[1].total, 1u);
  EXPECT_EQ(phong.cells[1].known, 1u);
  EXPECT_EQ(phong.cells[1].text(), "0/1*") << "only a known failure";
  EXPECT_EQ(phong.cells[2].total, 2u);
  EXPECT_EQ(phong.cells[2].passed, 1u);
  EXPECT_EQ(phong.cells[2].failed, 1u);
  EXPECT_EQ(phong.cells[2].text(), "1/2!");
  EXPECT_EQ(phong.cells[3].text(), "1/1");

  const MatrixRow& vertex = m.rows[1];
  EXPECT_EQ(vertex.cells[0].errors, 1u);
  EXPECT_EQ(vertex.cells[0].text(), "0/1!") << "an error is as loud as a failure";

  const MatrixRow& lambert = m.rows[2];
  EXPECT_EQ(lambert.cells[2].text(), "2/2") << "a known failure that passed counts as passed";
  size_t total = 0;
  for (const MatrixRow& row : m.rows)
    for (const MatrixCell& cell : row.cells) total += cell.total;
  EXPECT_EQ(total, report.results.size()) << "every result is in exactly one matrix cell";
}

TEST(SummaryMatrix, WorstErrorPerRow) {
  const SummaryMatrix m = build_summary_matrix(test::matrix_report());
  EXPECT_TRUE(m.rows[0].measured);
  EXPECT_DOUBLE_EQ(m.rows[0].worst_max_abs, 0.2) << "the largest over the row's columns and shapes, known ones too";
  EXPECT_FALSE(m.rows[1].measured) << "an error drew nothing, so it has no error to show";
  EXPECT_TRUE(std::isnan(m.rows[2].worst_max_abs)) << "NaN is worse than 0.5";
  // The same as a share of each cell's threshold (2e-3 here).
  EXPECT_DOUBLE_EQ(m.rows[0].worst_of_threshold, 100.0);
  EXPECT_TRUE(std::isnan(m.rows[2].worst_of_threshold));
  RunReport lut;
  lut.results = {{.case_name = "warn", .variant = "pixel_lut", .language = "glsl", .backend = "gl", .path = "glsl",
                  .shape = "cube", .status = CellStatus::pass, .metrics = {.max_abs = 0.03}, .interior_threshold = 0.1},
                 {.case_name = "warn", .variant = "pixel_lut", .language = "glsl", .backend = "gl", .path = "glsl",
                  .shape = "cone", .status = CellStatus::pass, .metrics = {.max_abs = 0.01}, .interior_threshold = 0.0125}};
  // Kept by value: a reference into the temporary's rows dangled (ASan, scripts/fuzz --ci).
  const SummaryMatrix lut_matrix = build_summary_matrix(lut);
  const MatrixRow& row = lut_matrix.rows.at(0);
  EXPECT_DOUBLE_EQ(row.worst_max_abs, 0.03);
  EXPECT_DOUBLE_EQ(row.worst_of_threshold, 0.8) << "the nearest to its own threshold, not the largest error";
  EXPECT_EQ(percent_of_threshold(0.8), "80%");
  EXPECT_EQ(percent_of_threshold(0.004), "<1%");
  EXPECT_EQ(percent_of_threshold(6.5), "650%");
  EXPECT_EQ(percent_of_threshold(65), "65x");
  EXPECT_EQ(percent_of_threshold(93592.1), "9.36e+04x");
}

TEST(SummaryMatrix, ListsTheCellsThatDidNotPass) {
  const RunReport report = test::matrix_report();
  const SummaryMatrix m = build_summary_matrix(report);
  EXPECT_EQ(m.rows[0].cells[2].problems, (std::vector<size_t>{1}));
  EXPECT_EQ(m.rows[0].cells[1].problems, (std::vector<size_t>{3}));
  EXPECT_EQ(m.rows[1].cells[0].problems, (std::vector<size_t>{4}));
  EXPECT_TRUE(m.rows[0].cells[3].problems.empty());
  EXPECT_TRUE(m.rows[2].cells[2].problems.empty());
}

}  // namespace
}  // namespace shaderbed
