#pragma once
// `shaderbed bench`: the speed of shaderbed itself, in one run. The whole suite as its own
// process with its caches cold, warm and off (draws untimed: no warm-up or timed repeats,
// so its wall time is the suite's own work) and where the cold run's time went (drivers vs
// shaderbed); one cell per process, cold and warm; the start-up of commands that draw
// nothing; then a few cells drawn by the drivers against the CPU reference rendering the
// same scene.
#include <functional>
#include <string>
#include <vector>

#include "backends/Backend.h"
#include "bench/ProcessCost.h"
#include "bench/ReferenceVsDrivers.h"
#include "bench/SuiteCost.h"
#include "core/Error.h"
#include "report/Results.h"

namespace shaderbed::bench {

struct BenchOptions {
  std::string cases_dir;                 // "" = the library's
  std::vector<std::string> cases;        // the suite's cases; empty = all (the default suite)
  int size = 256;
  int jobs = 0;                          // suite workers; 0 = one per core, as `run`
  std::string out_dir;                   // "" = no images written (no I/O part)
  std::vector<ComparedCell> compared;    // cells for the reference-vs-drivers timing
  int runs = 9;                          // timed repeats of those, and starts of each timed process
  std::vector<std::string> cell_args;    // the one cell timed as a process; empty = default_cell_args()
  // Progress: a step starting, and the suite's cells as they finish.
  std::function<void(const std::string& step)> on_step;
  std::function<void(size_t done, size_t total)> on_cell;
};

// The cells compared by default: a cheap and an expensive model, on two shapes.
std::vector<ComparedCell> default_compared_cells();

struct BenchReport {
  ToolVersions tools;
  int size = 0;
  int jobs = 0;                          // as asked
  std::vector<std::string> cases;        // as asked; empty = all
  TimingRequest suite_timing;            // what the suite's draws were: once each, untimed
  SuiteCost suite;                       // the cold suite's parts (processes.cold.cost)
  // The cold suite process's CPU time (user + sys, every thread: workers and the drivers'
  // own rasteriser threads): what the parts' thread wall times cost in CPU.
  double suite_cpu_ms = 0;
  size_t suite_failures = 0;             // cells that drew but failed the comparison
  ProcessCosts processes;
  std::vector<ReferenceVsDrivers> comparisons;
};

Result<BenchReport> run_bench(const BenchOptions& options);

}  // namespace shaderbed::bench
