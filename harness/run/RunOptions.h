#pragma once
// A run's options, split by who reads them: what selects the suite's cells (the planner),
// what a cell needs to be drawn and judged (each worker's GroupRunner), and how isolated
// workers are supervised (the supervisor). Workers receive the first two only
// (run/WorkerOptions.h).
#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "backends/Backend.h"
#include "report/Results.h"

namespace shaderbed {

// Which cases, and which of their cells. Filters: empty = all.
struct SuiteSelection {
  std::string cases_dir;                 // folder of *.toml case files; "" = the library's
  std::vector<std::string> cases;
  std::vector<std::string> variants;     // vertex, pixel, ...
  std::vector<std::string> backends;     // vulkan, gl
  std::vector<std::string> paths;        // spirv, glsl, cross (backends/Backend.h)
  std::vector<std::string> languages;    // every language a case has
  std::vector<std::string> shapes;       // sphere, cube, cone, torus
  std::vector<std::string> params;       // "name=value[,value...]" overrides
  std::string shard;                     // "I/N": run only this shard of the cell groups
  bool operator==(const SuiteSelection&) const = default;
};

// What every cell is drawn and judged with.
struct CellSettings {
  int size = 256;
  std::string out_dir;                   // images go here; empty = no images
  std::string save_images_dir;           // --save-images: every render, exact, with a manifest (run/StoredImages.h)
  std::string against_dir;               // --against: judge every cell against its image stored there
  TimingRequest timing{.warmup = 1, .runs = 6};   // 6: the fewest whose [min, max] is a 95 % CI of the median
  int mesh_slices = 0;                   // > 0: every shape at this density (make_shape), not the case's
  bool relaxed_precision = false;        // compile with floats declared relaxed (compile/RelaxedPrecision.h)
  // Judge every variant against the per-pixel model, so a per-vertex variant's error is what
  // it loses by shading at vertices (sweeps), not how faithful its port is (the default).
  bool per_pixel_reference = false;
  // Warn of case bindings no variant reads: only a run of every variant can tell (a
  // --variant filter would compile the others just for it).
  bool unused_binding_warnings = true;
  // --twin: every drawn cell also drawn by the shader's twin in this precision ("double",
  // "float", "half"; "" = off), and CellResult::twin filled.
  std::string twin;
  // Which cells' images --out keeps: "failing" (every cell that did not pass, and the
  // references they are judged against), "all", or "none". A green run writes no images.
  std::string keep_images = "failing";
  bool operator==(const CellSettings&) const = default;
};

// Isolation (run/IsolatedRun.h): with a worker binary (the shaderbed executable), cells
// run in child processes that the run supervises, so a compiler crash, a runaway
// allocation or a draw that never ends is one error cell and the run goes on; "" runs
// them in this process.
struct WorkerSupervision {
  // Worker threads or processes, each with its own Vulkan device and GL context; 0 = one
  // per core. Whole case x variant bundles go to one worker, so each pipeline is built once.
  int jobs = 0;
  std::string worker_binary;
  double compile_timeout_s = 30;   // compiling one program's stages (front ends, SPIR-V tools, SPIRV-Cross)
  double draw_timeout_s = 10;      // one cell's draw: pipeline build, warm-up and timed repeats
  // Any other step (start-up, the reference, judging, writing, twin, divergence); 0 = by
  // the image size (step_timeout_for_size), generous enough for a legitimate 4096 px run.
  double step_timeout_s = 0;
  size_t worker_memory_mb = 8192;  // a worker's address space (a run at 256 px peaks near 1.1 GB)
};

// The default deadline of a step other than compiling and drawing: a minute up to 512 px,
// growing with the pixels (a CPU reference, a twin and the judging scale with them): 16
// minutes at 2048 px, where a model reference takes about 4 s and a float twin about 20 s,
// so a legitimate run on a busy machine is not killed and a stopped worker is noticed.
inline double step_timeout_for_size(int size) {
  const double pixels = double(size) * double(size) / (512.0 * 512.0);
  return 60.0 * (pixels > 1 ? pixels : 1);
}

// Called before each step a worker takes ("reference", "compile", "draw", "judge",
// "write", "twin", "divergence", "attribution"), from the worker thread; an isolated
// worker reports it to the supervisor, which gives every step a deadline.
using StepObserver = std::function<void(const std::string& cell_id, const char* step)>;

struct RunOptions {
  SuiteSelection select;
  CellSettings cell;
  WorkerSupervision workers;
  std::string expectations;   // known-failures TOML file, "" = none
  // The report files the command will write after the run (path, option): refused before
  // anything is drawn when one is an input of the run (a case, shader or texture file).
  std::vector<std::pair<std::string, std::string>> report_files;
  // Progress; called from the worker threads, one call at a time.
  std::function<void(size_t done, size_t total, const CellResult&)> on_cell;
  StepObserver on_step;
};

// The settings the run's cells get: the options' own, with what the selection decides.
inline CellSettings cell_settings(const RunOptions& o) {
  CellSettings s = o.cell;
  s.unused_binding_warnings = o.select.variants.empty();
  return s;
}

}  // namespace shaderbed
