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
//                    "status", "message", "series", "label", "pareto"}],
//        "chart": {"png", "svg"}}                            (when a chart was written)
#include <cstdio>
#include <string>

#include "core/Error.h"
#include "plot/SpeedErrorChart.h"
#include "sweep/Sweep.h"

namespace shaderbed {

void print_sweep_table(const SweepResult& sweep, std::FILE* out);
std::string sweep_json(const SweepResult& sweep, const ChartFiles* chart);
Result<void> write_sweep_json(const SweepResult& sweep, const ChartFiles* chart, const std::string& path);

// Time (draw wall median) across, interior RMSE up, one series per variant, the Pareto
// front marked; out_stem.png and out_stem.svg.
Result<ChartFiles> write_sweep_chart(const SweepResult& sweep, const std::string& out_stem);

}  // namespace shaderbed
