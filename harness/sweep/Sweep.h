#pragma once
// `shaderbed sweep`: one case rendered at every point of a parameter space (case
// parameters, LUT size, tessellation, precision) and every variant, each point measured
// for error against the reference, draw time and instruction count, so variants can be
// placed on one speed-against-error chart.
//
// Each point is one cell (variant x language x backend x path x shape) at one combination
// of axis values. A variant that does not read an axis (a LUT size for an arithmetic
// variant) is drawn once, at the first combination, as a fixed point of comparison.
// The Pareto front of time against RMSE is taken per scene (SweepPoint::scene): a LUT size
// or a mesh density is a choice between ways of drawing one scene, a roughness is another
// scene.
// Points are drawn one at a time (no parallel workers) so their timings are comparable.
// Every point's error is against the per-pixel model in double precision: a per-vertex
// variant's error is what shading at vertices loses, a LUT variant's what the table loses.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "backends/Backend.h"
#include "core/Error.h"
#include "report/Results.h"
#include "sweep/SweepAxis.h"

namespace shaderbed {

inline constexpr size_t kDefaultMaxSweepPoints = 10000;   // --max-points

struct SweepOptions {
  std::string cases_dir;                 // "" = default_cases_dir()
  std::string case_name;
  std::vector<std::string> variants;     // empty = every variant of the case
  std::vector<std::string> languages;    // empty = glsl when the case has it, else its first
  std::vector<std::string> backends;     // empty = vulkan
  std::vector<std::string> shapes;       // empty = sphere
  std::vector<SweepAxis> axes;
  std::vector<std::string> precisions;   // "fp32", "relaxed"; empty = fp32
  int size = 256;
  TimingRequest timing{.warmup = 2, .runs = 9};   // 9 runs: the median's CI covers 96 %
  std::function<void(size_t done, size_t total, const std::string& what)> on_step;   // progress
  // Combinations of axis values x precisions allowed before anything is drawn: the axes
  // multiply, and 121,000 points is most of two hours. Over it, run_sweep refuses up front.
  size_t max_points = kDefaultMaxSweepPoints;
  // Asked before each point: a signal name ("SIGINT") ends the sweep there, with the points
  // finished so far (SweepResult::interrupted_by); "" goes on.
  std::function<std::string()> stop_requested;
};

struct SweepPoint {
  std::map<std::string, double> axis_values;   // the axes this point's variant reads
  // The point's scene: its values of the axes that change what is drawn (case parameters),
  // as opposed to how it is drawn (variant, precision, LUT size, tessellation). Points
  // compete for the Pareto front, and share a chart, only within one scene.
  std::string scene;                           // "" = the case's own parameters
  std::map<std::string, std::string> cell;     // variant, precision, language, backend, path, shape
  std::string series;                          // chart series: variant (+ precision, language, backend)
  std::string label;                           // chart label: the axis values, or the variant
  double rmse = 0, max_abs = 0;                // interior error against the reference
  double time_ms = 0, time_low_ms = 0, time_high_ms = 0;   // draw wall median and its CI
  double driver_clock_ms = 0;                  // the driver's own clock (docs/timing.md)
  double build_ms = 0;                         // pipeline build + JIT, 0 when cached
  int instructions = 0, vertex_instructions = 0, fragment_instructions = 0;   // SPIR-V, as drawn
  // SH cases: rmse and max_abs are against the exact lighting integral (the truncation and
  // compression the axes trade), and what the approximation costs besides the draw.
  double precompute_ms = 0;
  double bytes_per_vertex = 0;
  CellStatus status = CellStatus::error;
  std::string message;
  bool pareto = false;                         // on its scene's speed/error Pareto front
};

struct SweepResult {
  std::string case_name;
  std::vector<SweepAxis> axes;
  std::vector<std::string> precisions;
  int size = 0;
  TimingRequest timing;
  std::vector<SweepPoint> points;
  RunReport cells;                             // every cell drawn, for the HTML report
  std::string interrupted_by;                  // "SIGINT", "SIGTERM": stopped early; "" = every point drawn
  size_t steps_done = 0, steps_planned = 0;    // points (combinations x precisions) drawn and planned
};

Result<SweepResult> run_sweep(const SweepOptions& options);

}  // namespace shaderbed
