#include "report/ConsoleSummary.h"

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "report/ConsoleColour.h"
#include "report/Markup.h"
#include "report/SummaryMatrix.h"

namespace shaderbed {

void print_summary(const RunReport& report, std::FILE* out, bool colour) {
  const SummaryMatrix m = build_summary_matrix(report);
  if (m.rows.empty()) return;
  // Text grid: 3 header lines, then one line per row; columns: case, variant, the matrix
  // columns, worst error, worst share of the threshold.
  const size_t columns = m.columns.size() + 4;
  std::vector<std::vector<std::string>> lines(3, std::vector<std::string>(columns));
  std::vector<std::vector<Tint>> tints(3, std::vector<Tint>(columns, Tint::none));
  lines[2][0] = "case";
  lines[2][1] = "variant";
  std::vector<bool> group_start(columns, false);   // a language's first column: wider gap before it
  for (size_t c = 0; c < m.columns.size(); ++c) {
    const MatrixColumn& col = m.columns[c];
    const bool new_language = c == 0 || m.columns[c - 1].language != col.language;
    const bool new_backend = new_language || m.columns[c - 1].backend != col.backend;
    group_start[c + 2] = new_language;
    if (new_language) lines[0][c + 2] = col.language;
    if (new_backend) lines[1][c + 2] = col.backend;
    lines[2][c + 2] = col.path;
  }
  group_start[columns - 2] = true;
  lines[1][columns - 2] = "worst";
  lines[2][columns - 2] = "max err";
  lines[2][columns - 1] = "of tol";
  for (size_t r = 0; r < m.rows.size(); ++r) {
    const MatrixRow& row = m.rows[r];
    std::vector<std::string> line(columns);
    std::vector<Tint> tint(columns, Tint::none);
    // The case once per block of its variants, so the eye finds it.
    if (r == 0 || m.rows[r - 1].case_name != row.case_name) line[0] = row.case_name;
    line[1] = row.variant;
    for (size_t c = 0; c < row.cells.size(); ++c) {
      const MatrixCell& cell = row.cells[c];
      line[c + 2] = cell.empty() ? "-" : cell.text();
      if (!cell.empty() && cell.skipped != cell.total)
        tint[c + 2] = cell.failed + cell.errors ? Tint::fail : cell.known ? Tint::warn : Tint::pass;
    }
    line[columns - 2] = row.measured ? markup::sci(row.worst_max_abs) : "-";
    line[columns - 1] = row.measured ? percent_of_threshold(row.worst_of_threshold) : "-";
    lines.push_back(std::move(line));
    tints.push_back(std::move(tint));
  }
  std::vector<size_t> width(columns, 0);
  for (const auto& line : lines)
    for (size_t c = 0; c < columns; ++c) width[c] = std::max(width[c], line[c].size());
  for (size_t l = 0; l < lines.size(); ++l) {
    const auto& line = lines[l];
    std::string text;
    // Padded first, tinted after: the escape codes take no room on the screen.
    for (size_t c = 0; c < columns; ++c)
      text += fmt::format("{}{}", c == 0 ? "" : group_start[c] ? "   " : "  ",
                          tinted(fmt::format("{:<{}}", line[c], width[c]), tints[l][c], colour));
    while (!text.empty() && text.back() == ' ') text.pop_back();
    fmt::print(out, "{}\n", text);
  }
  fmt::print(out,
             "\nn/m: n of m shapes passed; ! a new failure or error (listed below); * known failures only; - not run.\n"
             "worst max err: the row's largest interior error; of tol: the largest share of its cell's threshold.\n");
}

}  // namespace shaderbed
