#pragma once
// What shaderbed costs as the processes a user and a CI matrix start: the suite with its
// caches cold, warm and off; one cell as its own process, cold and warm; and the start-up
// of commands that draw nothing. Each is the running binary started as a child process,
// timed by the wall clock from spawn to exit, side by side in one bench run. A private
// cache folder (SHADERBED_CACHE_DIR) per state keeps the user's caches out of it.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bench/SuiteCost.h"
#include "core/Error.h"
#include "timing/MedianInterval.h"

namespace shaderbed::bench {

// The engine's speed goals (docs/timing.md), printed beside what was measured.
struct ProcessGoals {
  static constexpr double warm_suite_of_cold = 0.25;   // warm suite wall / cold suite wall
  static constexpr double warm_suite_ms = 2500;        // the default suite, warm, 2 cores
  static constexpr double cold_suite_of_jit = 1.3;     // cold suite wall / (pipeline build / workers)
  static constexpr double warm_cell_ms = 60;
  static constexpr double cold_cell_ms = 154;          // below VkRunner's cold process on this machine kind
  static constexpr double help_ms = 30;
  static constexpr double twin_suite_of_warm = 2;      // warm suite with --twin double / without
};

// One command started `runs` times.
struct ProcessTiming {
  std::string label;              // "one cell, warm caches"
  std::string command;            // the arguments after the binary, as typed
  std::vector<double> wall_ms;    // spawn to exit, per run
  double cpu_ms = 0;              // median user + sys of the runs
  MedianInterval wall;            // of wall_ms
};

// The suite as one process (draws untimed), its parts from the JSON it wrote.
struct SuiteProcess {
  std::string state;              // "cold", "warm", "off", "twin" (warm, --twin double)
  double wall_ms = 0;             // the process, start-up included
  double cpu_ms = 0;
  SuiteCost cost;                 // from its results file
  ToolVersions tools;             // the same
  size_t failures = 0;            // cells that drew but failed
};

struct ProcessCosts {
  SuiteProcess cold, warm, off;
  SuiteProcess twin;                           // warm caches, every cell also drawn by its double twin
  ProcessTiming cell_cold, cell_warm;          // one cell per process
  std::vector<ProcessTiming> startup;          // --help, eval, merge
  // A failing port's cell as `run` judges it (its convention fits and divergence included)
  // and as `explain` explains its worst pixel, side by side; empty without the corpus.
  std::vector<ProcessTiming> failing_cell;
};

struct ProcessOptions {
  std::vector<std::string> suite_args;         // run's selection: --case, --size, --jobs, --cases-dir, --out
  std::vector<std::string> cell_args;          // the one cell's selection
  int size = 256;                              // the failing cell's image size
  int runs = 9;                                // per timed command
  std::function<void(const std::string&)> on_step;
};

// The one cell bench times as a process: phong per pixel in GLSL on Vulkan, on the sphere
// (what VkRunner's comparable test draws), untimed.
std::vector<std::string> default_cell_args();

// The failing cell bench times: tests/differential's tinted_diffuse port with the light
// negated, GLSL on Vulkan, on the sphere; nothing when the source tree is not there.
std::optional<std::pair<std::vector<std::string>, std::vector<std::string>>> failing_cell_commands(int size);

Result<ProcessCosts> measure_processes(const ProcessOptions& options);

}  // namespace shaderbed::bench
