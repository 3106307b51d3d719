#pragma once
// One case x variant x shape group run on one worker's backends: the group's reference
// (run/CellReference.h) prepared, every cell compiled, drawn (run/CellDraw.h), judged and
// its images written, then the group's attribution and, for failures, the convention fits.
// A worker keeps one GroupRunner for all its groups: programs, meshes, LUTs and what the
// references prepare are shared between them.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "report/Results.h"
#include "run/CellDivergence.h"
#include "run/CellPlan.h"
#include "run/RunOptions.h"
#include "run/StoredImages.h"
#include "scene/Scene.h"

namespace shaderbed {

class GroupRunner {
 public:
  // `gl_programs`: compile GL-target modules too (false: no cell of the run draws on GL).
  // `on_step`: told before each step, of a cell (compile, draw, judge, write, twin,
  // divergence) or, with the group's case/variant/shape for a cell id, of the group as a
  // whole (reference, attribution); may be empty.
  GroupRunner(const CellSettings& settings, const SceneSetup& scene, const StoredReferences& stored, bool gl_programs,
              StepObserver on_step = {});
  ~GroupRunner();
  GroupRunner(const GroupRunner&) = delete;
  GroupRunner& operator=(const GroupRunner&) = delete;

  // Every cell of the group, in the group's order.
  std::vector<CellResult> run(const CellGroup& g);

  // The next run() also explains one pixel of cell `cell_id` (`shaderbed explain`): `pixel`,
  // else where the cell is furthest from its reference. take_explanation() has it after.
  void request_explanation(std::string cell_id, std::optional<twin::PixelAt> pixel);
  std::optional<Result<PixelExplanation>> take_explanation();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace shaderbed
