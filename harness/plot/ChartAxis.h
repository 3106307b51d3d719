#pragma once
// One axis of a chart, decided from the values it has to show: linear or log, the
// displayed range, and where values that cannot be drawn where they are go instead
// (<= 0 on a log axis, NaN/Inf), so that no point silently disappears.
#include <span>
#include <string>
#include <string_view>

namespace shaderbed {

enum class AxisScale {
  automatic,  // log when the positive finite values span more than two decades
  linear,
  log,
};

struct ChartAxis {
  bool log = false;
  double low = 0, high = 1;  // the displayed range
  // Log axis only: values <= 0 are drawn at `floor` (a decade below the smallest
  // positive value); `clamped` counts them. 0 and 0 when nothing was clamped.
  double floor = 0;
  int clamped = 0;
  // Where NaN/+Inf (high) and -Inf (low) values are drawn: just inside the range edges,
  // in a margin the finite values do not use.
  double non_finite_low = 0, non_finite_high = 1;
  // One line for the chart when this axis draws something other than asked: values
  // clamped to the floor, or log requested but impossible. Empty otherwise.
  std::string note;

  // The coordinate a value is drawn at.
  double position(double value) const;
};

// `name` ("cost", "error") only words the note.
ChartAxis plan_axis(std::span<const double> values, AxisScale requested, std::string_view name);

}  // namespace shaderbed
