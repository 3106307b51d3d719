#pragma once
// A sweep's views: the console table, the JSON file and the speed-against-error chart.
//
// JSON: {"case", "size", "timing": {"warmup", "runs"}, "axes": [{"name", "values"}],
//        "precisions": [...], "tools": {...},
//        "points": [{"params": {axis: number, ..., "variant", "precision", "language",
//                               "backend", "path", "shape"},
//                    "rmse", "max_abs",                      (interior, against the reference)
//                    "time_ms", "time_ci_ms": [low, high],   (draw wall median, docs/timing.md)
//                    "driver_clock_ms", "build_ms",
//                    "instructions", "instructions_by_stage": {"vertex", "fragment"},
//                    "status", "message", "series", "label", "scene", "pareto"}],
//        "charts": [{"scene", "png", "svg"}]}                (one per scene, when written)
#include <cstdio>
#include <string>

#include "core/Error.h"
#include "plot/SpeedErrorChart.h"
#include "sweep/Sweep.h"

namespace shaderbed {

void print_sweep_table(const SweepResult& sweep, std::FILE* out);
struct SceneChart {
  std::string scene;   // SweepPoint::scene
  ChartFiles files;
};

std::string sweep_json(const SweepResult& sweep, const std::vector<SceneChart>& charts);

// Per scene: time (draw wall median) across, interior RMSE up, one series per variant,
// the Pareto front drawn. One scene: out_stem.png and .svg; several: out_stem-<i>.png ...
// in the order the scenes were first drawn.
Result<std::vector<SceneChart>> write_sweep_charts(const SweepResult& sweep, const std::string& out_stem);

}  // namespace shaderbed
