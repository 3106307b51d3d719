#pragma once
// A run whose cells execute in worker processes (run/CellWorker.h) under this process's
// supervision, so that nothing a user feeds shaderbed takes the run down:
//  - a worker that crashes (a compiler's SIGSEGV, a stack overflow in a parser, an
//    allocation past its address-space limit) costs one error cell naming the cell, the
//    step and the signal, "compiler crashed" when it was compiling; the cells that share
//    the crashed program are settled with it, and a new worker takes the group up again;
//  - every step has a deadline (--compile-timeout, --draw-timeout, --step-timeout for
//    start-up, the reference, judging, writing and the rest): a worker that misses one
//    is killed the same way, "error: timeout ... in <step>", and the next worker starts
//    with fresh backends;
//  - an allocation past the worker's limit is "out of memory", not a crash;
//  - a worker that dies before its hello is replaced a few times, then the cells it had
//    left are errors ("worker could not be started") and the run goes on;
//  - SIGINT, SIGTERM or SIGHUP stops the workers and returns the cells finished so far,
//    marked incomplete (RunReport::interruption); later signals are then ignored, so the
//    caller writes its reports before the process ends.
// Workers live across groups, so compile caches, Mesa's caches and pipelines stay warm;
// a worker is replaced only after a crash or a timeout.
#include <optional>
#include <vector>

#include "compile/CompileCache.h"
#include "report/Results.h"
#include "run/Runner.h"

namespace shaderbed {

struct IsolatedResults {
  std::vector<CellResult> results;
  ToolVersions tools;          // from the first worker's backends
  int workers = 0;             // workers started, replacements included
  std::optional<Interruption> interruption;
  CompileCacheCounts compiles;
};

// Runs plan's groups on min(jobs, bundles) workers (options.worker_binary, started as
// "WORKER __cell-worker"). An Error only when no worker of the run could start at all.
Result<IsolatedResults> run_isolated(const RunOptions& options, const SuitePlan& plan);

}  // namespace shaderbed
