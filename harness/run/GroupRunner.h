#pragma once
// One case x variant x shape group run on one worker's backends: the reference (a model,
// the original's render, or stored images), every cell compiled, drawn, judged and its
// images written, then the group's attribution and, for failures, the convention fits.
// A worker keeps one GroupRunner for all its groups: programs, meshes and LUTs are
// shared between them.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "report/Results.h"
#include "run/CellPlan.h"
#include "run/Runner.h"
#include "run/StoredImages.h"
#include "scene/Scene.h"

namespace shaderbed {

// The stored runs this run compares with, loaded (and checked) before anything is drawn.
struct StoredReferences {
  std::map<std::string, StoredRun> runs;                  // by folder
  std::map<std::string, std::string> toolchain_notes;     // by folder: "" when drawn alike
};

class GroupRunner {
 public:
  GroupRunner(const RunOptions& o, const SceneSetup& scene, const StoredReferences& stored);
  ~GroupRunner();
  GroupRunner(const GroupRunner&) = delete;
  GroupRunner& operator=(const GroupRunner&) = delete;

  // Every cell of the group, in the group's order (cells the options skip are left out).
  std::vector<CellResult> run(const CellGroup& g);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Every stored run the options and the selected cases name, checked against this run's
// image size before anything is drawn; a different toolchain is noted, not refused.
Result<StoredReferences> load_stored_references(const RunOptions& o, const std::vector<Case>& cases,
                                                const ToolVersions& tools);

}  // namespace shaderbed
