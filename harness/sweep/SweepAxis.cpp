#include "sweep/SweepAxis.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "prt/ShCase.h"

namespace shaderbed {
namespace {

Result<double> number(const std::string& axis, const std::string& text) {
  double v = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
    return fail(ErrorStage::options, fmt::format("--param {}: '{}' is not a number", axis, text));
  return v;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t at; (at = text.find(separator, start)) != std::string::npos; start = at + 1)
    parts.push_back(text.substr(start, at - start));
  parts.push_back(text.substr(start));
  return parts;
}

// Counts: LUT sizes, mesh slices, and the SH cases' bands, rays, clusters and the like.
bool integer_axis(const std::string& name) {
  return name == "lut_size" || name == "lut_rows" || name == kTessellationAxis || is_sh_approximation_parameter(name);
}

}  // namespace

Result<SweepAxis> parse_sweep_axis(const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    return fail(ErrorStage::options, fmt::format("--param '{}' is not NAME=LO:HI:STEPS[:lin|:log]", text));
  SweepAxis axis{text.substr(0, eq), {}, integer_axis(text.substr(0, eq))};
  const std::vector<std::string> parts = split(text.substr(eq + 1), ':');
  if (parts.size() < 3 || parts.size() > 4)
    return fail(ErrorStage::options, fmt::format("--param '{}' is not NAME=LO:HI:STEPS[:lin|:log]", text));
  auto lo = number(axis.name, parts[0]);
  if (!lo) return std::unexpected(lo.error());
  auto hi = number(axis.name, parts[1]);
  if (!hi) return std::unexpected(hi.error());
  auto steps = number(axis.name, parts[2]);
  if (!steps) return std::unexpected(steps.error());
  if (*steps < 1 || *steps > 1000 || *steps != std::floor(*steps))
    return fail(ErrorStage::options, fmt::format("--param {}: STEPS must be a whole number in 1..1000, not {}", axis.name, parts[2]));
  bool log = *lo > 0 && *hi / *lo >= 8;
  if (parts.size() == 4) {
    if (parts[3] != "lin" && parts[3] != "log")
      return fail(ErrorStage::options, fmt::format("--param {}: spacing '{}' is neither lin nor log", axis.name, parts[3]));
    log = parts[3] == "log";
    if (log && (*lo <= 0 || *hi <= 0))
      return fail(ErrorStage::options, fmt::format("--param {}: log spacing needs LO and HI > 0", axis.name));
  }
  const int n = int(*steps);
  for (int i = 0; i < n; ++i) {
    const double t = n == 1 ? 0.0 : double(i) / (n - 1);
    double v = log ? *lo * std::pow(*hi / *lo, t) : *lo + (*hi - *lo) * t;
    if (axis.integer) v = std::round(v);
    if (axis.values.empty() || axis.values.back() != v) axis.values.push_back(v);
  }
  return axis;
}

std::string format_axis_value(double value) { return fmt::format("{:.6g}", value); }

}  // namespace shaderbed
