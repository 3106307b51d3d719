#pragma once
// The speed-vs-error chart of a sweep: every variant as one point (cost across, error
// up), one colour and marker per series, each point labelled, a measured cost's
// confidence interval as a horizontal error bar, the Pareto front drawn through its points. Drawn by gnuplot into a PNG (to look at) and an SVG (to inline
// into the HTML report).
#include <limits>
#include <string>
#include <vector>

#include "core/Error.h"
#include "plot/ChartAxis.h"

namespace shaderbed {

struct ChartPoint {
  std::string label;   // short: it is printed next to the point
  std::string series;  // points of one series share a colour and marker
  double cost = 0;     // e.g. GPU time; NaN/Inf allowed (drawn at the edge, flagged)
  double error = 0;    // e.g. interior RMSE; NaN/Inf allowed
  // The cost's confidence interval (a median's: timing/MedianInterval), drawn as an error
  // bar and used by the front (points within noise are not ordered). NaN = no interval.
  double cost_low = std::numeric_limits<double>::quiet_NaN();
  double cost_high = std::numeric_limits<double>::quiet_NaN();
};

struct ChartSpec {
  std::string title;
  std::string x_label = "cost";   // with units, as they should read: "GPU time per draw (ms)"
  std::string y_label = "error";  // "interior RMSE"
  AxisScale x_scale = AxisScale::automatic;
  AxisScale y_scale = AxisScale::automatic;
  int width = 960, height = 640;  // pixels of the PNG; the SVG's viewBox
};

struct ChartFiles {
  std::string png;  // out_stem + ".png"
  std::string svg;  // out_stem + ".svg": no XML declaration, no script, no external
                    // references, so its text can be pasted into an HTML page as is
};

// Writes out_stem.png and out_stem.svg (creating the parent directory). `gnuplot` is the
// program to run, a name looked up on PATH or a path. Nothing is written when gnuplot
// is missing or fails: it draws into a temporary directory first.
Result<ChartFiles> write_speed_error_chart(const std::vector<ChartPoint>& points, const ChartSpec& spec,
                                           const std::string& out_stem, const std::string& gnuplot = "gnuplot");

}  // namespace shaderbed
