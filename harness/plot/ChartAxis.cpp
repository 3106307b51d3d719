#include "plot/ChartAxis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

namespace shaderbed {
namespace {

constexpr double kDecadesForAutoLog = 2.0;
constexpr double kMarginFraction = 0.06;  // of the data span, each side

}  // namespace

double ChartAxis::position(double value) const {
  if (std::isnan(value) || value == std::numeric_limits<double>::infinity()) return non_finite_high;
  if (value == -std::numeric_limits<double>::infinity()) return non_finite_low;
  if (log && value <= 0) return floor;
  return value;
}

ChartAxis plan_axis(std::span<const double> values, AxisScale requested, std::string_view name) {
  ChartAxis axis;
  std::vector<double> finite, positive;
  bool has_nan_or_pos_inf = false, has_neg_inf = false;
  for (double v : values) {
    if (std::isfinite(v)) {
      finite.push_back(v);
      if (v > 0) positive.push_back(v);
    } else {
      (v == -std::numeric_limits<double>::infinity() ? has_neg_inf : has_nan_or_pos_inf) = true;
    }
  }

  const auto [min_pos, max_pos] = positive.empty() ? std::pair(0.0, 0.0)
                                                   : std::pair(*std::ranges::min_element(positive), *std::ranges::max_element(positive));
  switch (requested) {
    case AxisScale::linear: axis.log = false; break;
    case AxisScale::automatic: axis.log = !positive.empty() && std::log10(max_pos / min_pos) > kDecadesForAutoLog; break;
    case AxisScale::log:
      axis.log = !positive.empty();
      if (!axis.log && !finite.empty()) axis.note = fmt::format("log {} axis requested, but no {} is positive: linear axis", name, name);
      break;
  }

  if (axis.log) {
    axis.clamped = static_cast<int>(finite.size() - positive.size());
    if (axis.clamped > 0) {
      axis.floor = min_pos / 10;
      axis.note = fmt::format("{} point{} with {} <= 0 drawn at {:.3g} (log axis)", axis.clamped,
                              axis.clamped == 1 ? "" : "s", name, axis.floor);
    }
  }

  // Work in the drawn coordinate (log10 on a log axis), where margins are even.
  auto to_draw = [&](double v) { return axis.log ? std::log10(v) : v; };
  auto from_draw = [&](double d) { return axis.log ? std::pow(10.0, d) : d; };
  double lo = 0, hi = 1;
  if (!finite.empty()) {
    lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (double v : finite) {
      const double d = to_draw(axis.position(v));
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
  }
  double margin = (hi - lo) * kMarginFraction;
  if (margin == 0) margin = axis.log ? 0.5 : (lo == 0 ? 1.0 : std::abs(lo) * 0.1);  // one value: give it room
  lo -= margin, hi += margin;
  // Non-finite values get their own strip past the margin, so they never sit on a finite point.
  if (has_neg_inf) axis.non_finite_low = from_draw(lo), lo -= margin;
  if (has_nan_or_pos_inf) axis.non_finite_high = from_draw(hi), hi += margin;
  axis.low = from_draw(lo), axis.high = from_draw(hi);
  if (!has_neg_inf) axis.non_finite_low = axis.low;
  if (!has_nan_or_pos_inf) axis.non_finite_high = axis.high;
  return axis;
}

}  // namespace shaderbed
