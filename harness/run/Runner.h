#pragma once
// Runs a suite: every case x variant x language x shape x backend x path cell is
// compiled, drawn, compared with the reference, and reported. Bad input (unknown case,
// backend, language or shape) is an Error; a cell that cannot be drawn is a result with
// status "error", so one broken shader never hides the others.
#include <memory>
#include <string>
#include <vector>

#include "backends/Backend.h"
#include "core/Error.h"
#include "report/Results.h"
#include "run/CellPlan.h"
#include "run/Expectations.h"
#include "run/RunOptions.h"

namespace shaderbed {

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

// The library's cases, ROOT/shaders/cases, ROOT being the first of: $SHADERBED_ROOT; the
// installed tree this binary sits in (bin/../share/shaderbed, core/InstalledTree.h); the
// source directory this binary was built from.
std::string default_cases_dir();

}  // namespace shaderbed
