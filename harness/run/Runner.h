#pragma once
// Runs a suite: every case x variant x language x shape x backend x path cell is
// compiled, drawn, compared with the reference, and reported. Bad input (unknown case,
// backend, language or shape) is an Error; a cell that cannot be drawn is a result with
// status "error", so one broken shader never hides the others.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "backends/Backend.h"
#include "core/Error.h"
#include "report/Results.h"
#include "run/CellPlan.h"
#include "run/Expectations.h"

namespace shaderbed {

struct RunOptions {
  std::string cases_dir;                 // folder of *.toml case files
  std::vector<std::string> cases;        // empty = all
  std::vector<std::string> variants;     // empty = all (vertex, pixel, ...)
  std::vector<std::string> backends;     // empty = vulkan, gl
  std::vector<std::string> languages;    // empty = every language a case has
  std::vector<std::string> shapes;       // empty = sphere, cube, cone, torus
  std::vector<std::string> params;       // "name=value[,value...]" overrides
  int size = 256;
  std::string out_dir;                   // images go here; empty = no images
  std::string save_images_dir;           // --save-images: every render, exact, with a manifest (run/StoredImages.h)
  std::string against_dir;               // --against: judge every cell against its image stored there
  std::string shard;                     // "I/N": run only this shard of the cell groups
  std::string expectations;              // known-failures TOML file, "" = none
  // Worker threads, each with its own Vulkan device and GL context; 0 = one per core.
  // Whole case x variant bundles go to one worker, so each pipeline is built once.
  int jobs = 0;
  TimingRequest timing{.warmup = 1, .runs = 6};   // 6: the fewest whose [min, max] is a 95 % CI of the median
  int mesh_slices = 0;              // > 0: every shape at this density (make_shape), not the case's
  bool relaxed_precision = false;   // compile with floats declared relaxed (compile/RelaxedPrecision.h)
  // Judge every variant against the per-pixel model, so a per-vertex variant's error is what
  // it loses by shading at vertices (sweeps), not how faithful its port is (the default).
  bool per_pixel_reference = false;
  // Progress; called from the worker threads, one call at a time.
  std::function<void(size_t done, size_t total, const CellResult&)> on_cell;

  // Isolation (run/IsolatedRun.h): with a worker binary (the shaderbed executable), cells
  // run in child processes that the run supervises, so a compiler crash, a runaway
  // allocation or a draw that never ends is one error cell and the run goes on; "" runs
  // them in this process.
  std::string worker_binary;
  double compile_timeout_s = 30;   // compiling one program's stages (front ends, SPIR-V tools, SPIRV-Cross)
  double draw_timeout_s = 10;      // one cell's draw: pipeline build, warm-up and timed repeats
  size_t worker_memory_mb = 8192;  // a worker's address space (a run at 256 px peaks near 1.1 GB)
  // Called before each step of a cell that runs untrusted input ("compile", "draw") and
  // after it ("judge"), from the worker thread; an isolated worker reports it to the
  // supervisor, which times the step.
  std::function<void(const std::string& cell_id, const char* step)> on_step;
};

// A run's plan: the selected cases (the groups point into them), the known failures, the
// backends it needs (not started: planning needs only their names) and the cell groups of
// its shard, in a deterministic order, so an isolated worker plans the same groups from
// the same options.
struct SuitePlan {
  std::vector<Case> cases;
  std::vector<KnownFailure> known;
  std::vector<std::string> backend_names;
  std::vector<BackendSlot> backends;
  std::vector<CellGroup> groups;
  size_t cells = 0;
};

// Bad input (an unknown case, model, backend, language or shape; a filter that selects
// nothing; a bad shard or expectations file) is an Error before anything starts.
Result<std::unique_ptr<SuitePlan>> plan_suite(const RunOptions& options);

// `g` with its cells on `backends`, started in the order of plan.backend_names.
CellGroup on_backends(const CellGroup& g, const SuitePlan& plan, std::vector<BackendSlot>& backends);

// Consecutive groups of one case x variant (they share programs, so one worker runs them
// all and builds each pipeline once), largest bundle first.
std::vector<std::vector<size_t>> bundles_of(const std::vector<CellGroup>& groups);

Result<RunReport> run_suite(const RunOptions& options);

// Results in one canonical order (by cell id), so shards merged equal one whole run.
void sort_results(RunReport& report);

// Where the source tree's shaders/cases folder is: $SHADERBED_ROOT/shaders/cases, else the
// source directory this binary was built from.
std::string default_cases_dir();

}  // namespace shaderbed
