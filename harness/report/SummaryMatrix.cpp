#include "report/SummaryMatrix.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include <fmt/format.h>

namespace shaderbed {
namespace {

// Position of `name` in the preferred order; unknown names after the known ones.
template <size_t N>
size_t rank(const std::array<const char*, N>& order, const std::string& name) {
  return size_t(std::find(order.begin(), order.end(), name) - order.begin());
}

auto column_key(const MatrixColumn& c) {
  static constexpr std::array<const char*, 3> languages{"hlsl", "cg", "glsl"};
  static constexpr std::array<const char*, 2> backends{"vulkan", "gl"};
  static constexpr std::array<const char*, 3> paths{"glsl", "spirv", "cross"};
  return std::tuple(rank(languages, c.language), c.language, rank(backends, c.backend), c.backend,
                    rank(paths, c.path), c.path);
}

// NaN is worse than any number: a cell whose error is not a number is the row's headline.
bool worse(double a, double b) { return std::isnan(a) ? !std::isnan(b) : !std::isnan(b) && a > b; }

}  // namespace

std::string MatrixCell::text() const {
  if (empty()) return "";
  if (skipped == total) return "skip";
  return fmt::format("{}/{}{}", passed, total - skipped, failed + errors ? "!" : known ? "*" : "");
}

std::string percent_of_threshold(double ratio) {
  if (std::isnan(ratio)) return "nan";
  if (std::isinf(ratio)) return "inf";
  if (ratio < 0.01) return "<1%";
  if (ratio < 10) return fmt::format("{:.0f}%", 100 * ratio);
  return fmt::format("{:.3g}x", ratio);   // far over: a factor reads better than "9359212%"
}

SummaryMatrix build_summary_matrix(const RunReport& report) {
  SummaryMatrix m;
  for (const CellResult& r : report.results) {
    const MatrixColumn c{r.language, r.backend, r.path};
    const auto before = [](const MatrixColumn& a, const MatrixColumn& b) { return column_key(a) < column_key(b); };
    const auto at = std::lower_bound(m.columns.begin(), m.columns.end(), c, before);
    if (at == m.columns.end() || column_key(*at) != column_key(c)) m.columns.insert(at, c);
  }
  std::map<std::pair<std::string, std::string>, size_t> row_of;
  for (size_t i = 0; i < report.results.size(); ++i) {
    const CellResult& r = report.results[i];
    auto [it, added] = row_of.try_emplace({r.case_name, r.variant}, m.rows.size());
    if (added) m.rows.push_back({r.case_name, r.variant, std::vector<MatrixCell>(m.columns.size())});
    MatrixRow& row = m.rows[it->second];
    const auto column = std::find_if(m.columns.begin(), m.columns.end(), [&](const MatrixColumn& c) {
      return c.language == r.language && c.backend == r.backend && c.path == r.path;
    });
    MatrixCell& cell = row.cells[size_t(column - m.columns.begin())];
    ++cell.total;
    if (r.status == CellStatus::pass) ++cell.passed;
    else if (r.status == CellStatus::fail) ++(r.known_failure ? cell.known : cell.failed);
    else if (r.status == CellStatus::skipped) ++cell.skipped;
    else ++cell.errors;
    if (r.status != CellStatus::pass && r.status != CellStatus::skipped) cell.problems.push_back(i);
    if (r.status != CellStatus::pass && r.status != CellStatus::fail) continue;   // an error drew nothing: no error to show
    const double e = r.metrics.max_abs, t = r.interior_threshold;
    // A relative tolerance has no single threshold: its share is measured per pixel.
    const double ratio = r.interior_threshold_rel > 0 ? r.metrics.tolerance_share
                         : t > 0                       ? e / t
                         : e > 0                       ? std::numeric_limits<double>::infinity()
                                                       : e;   // e: 0 or NaN
    if (!row.measured || worse(e, row.worst_max_abs)) row.worst_max_abs = e;
    if (!row.measured || worse(ratio, row.worst_of_threshold)) row.worst_of_threshold = ratio;
    row.measured = true;
  }
  return m;
}

}  // namespace shaderbed
