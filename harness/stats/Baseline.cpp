#include "stats/Baseline.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <boost/math/distributions/students_t.hpp>

#include <fmt/format.h>

namespace shaderbed::stats {
namespace {

int metric_value(const StatsEntry& e, const std::string& metric) {
  if (metric == "spirv") return e.spirv.total;
  if (metric == "spirv_os") return e.spirv_os.total;
  if (metric == "glsl_lines") return e.glsl_lines;
  return e.spirv_opt.total;
}

std::optional<Interval> interval(const std::vector<double>& xs, double& mean) {
  mean = 0;
  if (xs.empty()) return std::nullopt;
  for (double x : xs) mean += x;
  mean /= double(xs.size());
  if (xs.size() < 2) return std::nullopt;
  double ss = 0;
  for (double x : xs) ss += (x - mean) * (x - mean);
  const double sd = std::sqrt(ss / double(xs.size() - 1));
  const double half = t_critical_95(int(xs.size()) - 1) * sd / std::sqrt(double(xs.size()));
  return Interval{mean - half, mean + half};
}

std::string percent(long before, long after) {
  if (before == 0) return after == 0 ? "0.00%" : "+inf%";
  return fmt::format("{:+.2f}%", 100.0 * double(after - before) / double(before));
}

}  // namespace

Result<void> check_metric(const std::string& metric) {
  if (metric == "spirv" || metric == "spirv_opt" || metric == "spirv_os" || metric == "glsl_lines") return {};
  return fail(ErrorStage::options, "unknown metric '" + metric + "' (spirv, spirv_opt, spirv_os, glsl_lines)");
}

double t_critical_95(int df) {
  if (df < 1) return INFINITY;
  return boost::math::quantile(boost::math::complement(boost::math::students_t(df), 0.025));
}

Comparison compare(const StatsReport& baseline, const StatsReport& current, const std::string& metric) {
  Comparison c;
  c.metric = metric;
  std::map<std::string, int> before, after;
  for (const StatsEntry& e : baseline.entries)
    if (e.error.empty()) before[e.key()] = metric_value(e, metric);
  for (const StatsEntry& e : current.entries)
    if (e.error.empty()) after[e.key()] = metric_value(e, metric);
  std::vector<double> diffs, rels;
  for (const auto& [key, b] : before) {
    auto it = after.find(key);
    if (it == after.end()) {
      c.lost.push_back(key);
      continue;
    }
    const int a = it->second;
    c.total_before += b;
    c.total_after += a;
    if (a == b) {
      ++c.unchanged;
      continue;
    }
    c.affected_before += b;
    c.affected_after += a;
    ShaderChange ch{key, b, a};
    diffs.push_back(a - b);
    rels.push_back(100.0 * ch.relative());
    (a < b ? c.helped : c.hurt).push_back(ch);
  }
  for (const auto& [key, a] : after)
    if (!before.contains(key)) c.gained.push_back(key);
  // Most helped first (most negative relative change); most hurt first (most positive).
  std::stable_sort(c.helped.begin(), c.helped.end(),
                   [](const ShaderChange& x, const ShaderChange& y) { return x.relative() < y.relative(); });
  std::stable_sort(c.hurt.begin(), c.hurt.end(),
                   [](const ShaderChange& x, const ShaderChange& y) { return x.relative() > y.relative(); });
  c.mean_ci = interval(diffs, c.mean_change);
  c.percent_ci = interval(rels, c.mean_percent);
  return c;
}

std::string format_comparison(const Comparison& c) {
  const std::string what = c.metric == "glsl_lines" ? "GLSL lines" : c.metric + " instructions";
  std::string out;
  for (const ShaderChange& h : c.helped)
    out += fmt::format("helped:   {} {}: {} -> {} ({:+.2f}%)\n", h.key, what, h.before, h.after, 100.0 * h.relative());
  if (!c.helped.empty()) out += "\n";
  for (const ShaderChange& h : c.hurt)
    out += fmt::format("HURT:     {} {}: {} -> {} ({:+.2f}%)\n", h.key, what, h.before, h.after, 100.0 * h.relative());
  if (!c.hurt.empty()) out += "\n";
  out += fmt::format("total {} in shared shaders: {} -> {} ({})\n", what, c.total_before, c.total_after,
                     percent(c.total_before, c.total_after));
  out += fmt::format("{} in affected shaders: {} -> {} ({})\n", what, c.affected_before, c.affected_after,
                     percent(c.affected_before, c.affected_after));
  out += fmt::format("helped: {}\nHURT: {}\nunchanged: {}\n", c.helped.size(), c.hurt.size(), c.unchanged);
  const size_t n = c.helped.size() + c.hurt.size();
  if (c.mean_ci && c.percent_ci) {
    out += fmt::format("mean change: {:+.2f} ({:+.2f}%), n = {}\n", c.mean_change, c.mean_percent, n);
    out += fmt::format("95% mean confidence interval for {} value: {:+.2f} {:+.2f}\n", what, c.mean_ci->low,
                       c.mean_ci->high);
    out += fmt::format("95% mean confidence interval for {} %-change: {:+.2f}% {:+.2f}%\n", what, c.percent_ci->low,
                       c.percent_ci->high);
  } else if (n == 1) {
    out += fmt::format("mean change: {:+.2f} ({:+.2f}%), n = 1: no confidence interval\n", c.mean_change,
                       c.mean_percent);
  }
  if (n == 0) out += "No shader changed.\n";
  else if (c.inconclusive()) out += "Inconclusive result (value mean confidence interval includes 0).\n";
  else out += fmt::format("{} are {}.\n", what, c.mean_ci->high < 0 ? "helped" : "HURT");
  if (!c.lost.empty()) {
    out += fmt::format("\nLOST:   {} shaders\n", c.lost.size());
    for (const std::string& k : c.lost) out += "  " + k + "\n";
  }
  if (!c.gained.empty()) {
    out += fmt::format("\nGAINED: {} shaders\n", c.gained.size());
    for (const std::string& k : c.gained) out += "  " + k + "\n";
  }
  return out;
}

bool exceeds(const Comparison& c, double pct) { return c.affected_percent() > pct; }

}  // namespace shaderbed::stats
