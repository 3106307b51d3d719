#pragma once
// Baseline comparison in the manner of Mesa shader-db's report.py: per-shader helped /
// HURT lines sorted by relative change, totals over all shared shaders and over the
// affected ones, the mean change with a 95% confidence interval (Student's t) and
// "inconclusive" when that interval includes zero, and the shaders lost and gained.
#include <optional>
#include <string>
#include <vector>

#include "core/Error.h"
#include "stats/StatsReport.h"

namespace shaderbed::stats {

// Which number is compared: "spirv", "spirv_opt" (default), "spirv_os" (their totals) or
// "glsl_lines".
Result<void> check_metric(const std::string& metric);

struct ShaderChange {
  std::string key;    // case/variant/language/stage
  int before = 0, after = 0;
  double relative() const { return before == 0 ? (after == 0 ? 0.0 : 1.0) : double(after - before) / before; }
};

struct Interval {
  double low = 0, high = 0;
  bool includes_zero() const { return low <= 0 && high >= 0; }
};

struct Comparison {
  std::string metric;
  std::vector<ShaderChange> helped;   // fewer instructions, most helped (relative) first
  std::vector<ShaderChange> hurt;     // more instructions, most hurt (relative) first
  long total_before = 0, total_after = 0;         // shaders in both runs
  long affected_before = 0, affected_after = 0;   // shaders that changed
  int unchanged = 0;
  std::vector<std::string> lost, gained;          // only in the baseline / only in the new run
  // Over the affected shaders (n = helped + HURT >= 2), of after - before and of the
  // relative change; absent with fewer than two affected shaders.
  std::optional<Interval> mean_ci, percent_ci;
  double mean_change = 0, mean_percent = 0;
  bool inconclusive() const { return !mean_ci || mean_ci->includes_zero(); }
  // Change of the affected shaders' total, percent (0 when nothing changed).
  double affected_percent() const {
    return affected_before == 0 ? 0.0 : 100.0 * double(affected_after - affected_before) / affected_before;
  }
};

// Entries with a compile error are left out of both sides (a shader that stopped
// compiling is "lost", one that started compiling "gained").
Comparison compare(const StatsReport& baseline, const StatsReport& current, const std::string& metric = "spirv_opt");

std::string format_comparison(const Comparison&);

// --fail-above PCT: true when the affected shaders' total grew by more than PCT percent.
bool exceeds(const Comparison&, double percent);

// Two-sided 95% critical value of Student's t with `df` degrees of freedom.
double t_critical_95(int df);

}  // namespace shaderbed::stats
