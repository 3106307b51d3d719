#pragma once
// What an isolated run's supervisor and its worker processes say to each other
// (run/IsolatedRun.h). The supervisor writes the run's options as one JSON line on the
// worker's stdin (run/WorkerOptions.h), then one command a line: "group INDEX [SKIPPED-CELL-ID...]" runs a group
// of the plan both sides make from the same options. The worker answers on its events pipe,
// one line each:
//   hello <RunReport JSON: the toolchain of the backends it started>
//   step <cell id> <step>       before each step (reference, compile, draw, judge, write,
//                               twin, divergence, attribution); the supervisor gives each a deadline
//   cell <RunReport JSON holding one result>
//   done <disk hits> <compiles> <memory hits>   the group is finished (compile cache counts so far)
#include <string>
#include <string_view>

#include "compile/CompileCache.h"
#include "core/Error.h"
#include "report/Results.h"

namespace shaderbed {

// A worker's exit status when an allocation failed (its address space is limited): the
// supervisor reports "out of memory" rather than a crash of the step it was in.
inline constexpr int kWorkerOutOfMemoryExit = 86;

struct WorkerEvent {
  enum class Kind { hello, step, cell, done, unknown } kind = Kind::unknown;
  std::string cell_id;   // step
  std::string step;      // step: "reference", "compile", "draw", "judge", ...
  RunReport report;      // hello (tools), cell (one result)
  CompileCacheCounts compiles;   // done
};

Result<WorkerEvent> parse_worker_event(std::string_view line);

}  // namespace shaderbed
