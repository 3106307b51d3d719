#pragma once
// The run at a glance: one row per case/variant, one column per language x backend/path,
// each matrix cell counting the shapes that passed. The console summary and the HTML
// report both draw it, so a person reads the same verdict in either.
#include <string>
#include <vector>

#include "report/Results.h"

namespace shaderbed {

struct MatrixColumn {
  std::string language, backend, path;
  std::string label() const { return language + " " + backend + "/" + path; }   // "glsl vulkan/spirv"
};

struct MatrixCell {
  size_t total = 0;     // results in this case/variant/column (one per shape); 0 = no such cell
  size_t passed = 0;    // including known failures that passed
  size_t failed = 0;    // new failures
  size_t known = 0;     // known failures (expectations)
  size_t errors = 0;
  size_t skipped = 0;   // the path does not apply to the shader: not in passed/total's "run"
  std::vector<size_t> problems;   // indices into RunReport::results of the cells that did not pass

  bool empty() const { return total == 0; }
  // "4/4"; "2/4!" when a failure or error is new; "3/4*" when only known failures; "" if
  // empty; "skip" when every cell was skipped (skipped cells are left out of the count).
  std::string text() const;
};

struct MatrixRow {
  std::string case_name, variant;
  std::vector<MatrixCell> cells;   // parallel to SummaryMatrix::columns
  // The largest interior max error over the row's measured cells (errors drew nothing), and
  // the largest max error / interior threshold (how near the row is to failing: a LUT
  // variant's large error may sit well inside its derived threshold); NaN counts as the
  // worst. measured = false when no cell of the row was measured.
  double worst_max_abs = 0;
  double worst_of_threshold = 0;
  bool measured = false;
};

struct SummaryMatrix {
  // Only the columns some result has, ordered hlsl, cg, glsl (as `stats` does), then
  // vulkan before gl, then the GL paths glsl, spirv, cross; anything else after, by name.
  std::vector<MatrixColumn> columns;
  std::vector<MatrixRow> rows;     // in the report's order of first appearance
};

SummaryMatrix build_summary_matrix(const RunReport& report);

// "71%", "<1%", "650%", "65x", "9.36e+04x", "nan": MatrixRow::worst_of_threshold for people.
std::string percent_of_threshold(double ratio);

}  // namespace shaderbed
