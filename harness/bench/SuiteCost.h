#pragma once
// Where a suite run's time went: the drivers' work (pipeline build + JIT, draw, readback)
// against shaderbed's own (compile with glslang / SPIRV-Tools / SPIRV-Cross, the CPU
// reference, the comparison), from the per-cell times of a RunReport.
//
// The runner copies some times into several cells, so each is counted once here:
// "compile" once per program (case/variant/language), "reference" once per group
// (case/variant/shape); "build" is already 0 for cells that reused a cached pipeline.
// With several workers the parts add up to more than the wall time, so shares are of the
// summed parts, and what the parts do not explain is wall x workers - sum.
#include <string>
#include <vector>

#include "report/Results.h"

namespace shaderbed::bench {

enum class CostOwner { driver, shaderbed };

struct CostPart {
  std::string name;         // "build", "draw", "readback", "compile", "reference", "compare"
  std::string description;  // what the time is, for the table
  CostOwner owner = CostOwner::driver;
  double ms = 0;
  size_t count = 0;         // how many times it was paid (unique programs, groups, cells, builds)
};

struct SuiteCost {
  std::vector<CostPart> parts;   // drivers' first, then shaderbed's, in the table's order
  double driver_ms = 0;
  double shaderbed_ms = 0;
  double summed_ms = 0;          // driver_ms + shaderbed_ms
  double wall_ms = 0;
  int workers = 1;
  double worker_ms = 0;          // wall_ms x workers: the time the workers had
  double unaccounted_ms = 0;     // worker_ms - summed_ms (startup, case loading, LUTs, idle workers)
  size_t cells = 0;
  size_t errors = 0;             // cells with status "error": their parts are missing

  double driver_share() const { return summed_ms > 0 ? driver_ms / summed_ms : 0; }
  // The drivers' pipeline builds + JIT: what a cold suite cannot avoid (its "JIT floor" is
  // this divided by the workers).
  double driver_build_ms() const {
    for (const CostPart& p : parts)
      if (p.name == "build") return p.ms;
    return 0;
  }
  double shaderbed_share() const { return summed_ms > 0 ? shaderbed_ms / summed_ms : 0; }
};

// Unaccounted time is wall x report.workers - the summed parts.
SuiteCost suite_cost(const RunReport& report);

}  // namespace shaderbed::bench
