#include "bench/SuiteCost.h"

#include <algorithm>
#include <map>
#include <set>
#include <thread>
#include <tuple>

namespace shaderbed::bench {
namespace {

double time_of(const CellResult& r, const std::string& part) {
  const auto it = r.time_ms.find(part);
  return it == r.time_ms.end() ? 0 : it->second;
}

}  // namespace

SuiteCost suite_cost(const RunReport& report) {
  const int workers = report.workers;
  CostPart build{"build", "pipeline/program build + JIT", CostOwner::driver};
  CostPart draw{"draw", "draw (submit + wait)", CostOwner::driver};
  CostPart readback{"readback", "readback", CostOwner::driver};
  CostPart compile{"compile", "compile: glslang, SPIRV-Tools, SPIRV-Cross", CostOwner::shaderbed};
  CostPart reference{"reference", "CPU reference render (double)", CostOwner::shaderbed};
  CostPart precompute{"precompute", "SH precompute: transfer, light, tables", CostOwner::shaderbed};
  CostPart compare{"compare", "compare with the reference", CostOwner::shaderbed};
  CostPart io{"io", "image I/O: renders and error images (--out)", CostOwner::shaderbed};

  // The first cell of a program / group carries the time the others copy.
  std::set<std::tuple<std::string, std::string, std::string>> programs, groups;
  std::set<std::pair<std::string, std::string>> shapes;   // an SH case's precompute serves all its variants
  SuiteCost cost;
  for (const CellResult& r : report.results) {
    ++cost.cells;
    cost.errors += r.status == CellStatus::error;
    if (r.time_ms.contains("compile") && programs.insert({r.case_name, r.variant, r.language}).second) {
      compile.ms += time_of(r, "compile");
      ++compile.count;
    }
    if (r.time_ms.contains("reference") && groups.insert({r.case_name, r.variant, r.shape}).second) {
      reference.ms += time_of(r, "reference");
      ++reference.count;
    }
    if (r.sh && shapes.insert({r.case_name, r.shape}).second) {
      precompute.ms += r.sh->precompute_ms;
      ++precompute.count;
    }
    if (r.time_ms.contains("build") && !r.program_cached) {
      build.ms += time_of(r, "build");
      ++build.count;
    }
    for (CostPart* per_cell : {&draw, &readback, &compare, &io})
      if (r.time_ms.contains(per_cell->name)) {
        per_cell->ms += time_of(r, per_cell->name);
        ++per_cell->count;
      }
  }
  cost.parts = {build, draw, readback, compile, reference, precompute, compare, io};
  for (const CostPart& p : cost.parts) (p.owner == CostOwner::driver ? cost.driver_ms : cost.shaderbed_ms) += p.ms;
  cost.summed_ms = cost.driver_ms + cost.shaderbed_ms;
  cost.wall_ms = report.wall_ms;
  cost.workers = std::max(1, workers);
  cost.worker_ms = cost.wall_ms * cost.workers;
  cost.unaccounted_ms = cost.worker_ms - cost.summed_ms;
  return cost;
}

}  // namespace shaderbed::bench
