#pragma once
// The cells of a run, grouped by case x variant x shape: every render of a group shows
// the same scene, so attribution compares them with each other. Shards split whole
// groups, deterministically, so a shard can attribute its own failures.
#include <optional>
#include <string>
#include <vector>

#include "backends/Backend.h"
#include "twin/Precision.h"
#include "scene/CaseFile.h"

namespace shaderbed {

struct BackendSlot {
  std::string name;
  Result<std::unique_ptr<Backend>> backend = fail(ErrorStage::backend, "not started");
};

// A slot per backend the filter selects (empty = vulkan, gl), each started here; a backend
// that cannot start is an error in its slot, so its cells report it. "twin-double",
// "twin-float" and "twin-half" start the shader's twin (backends/twin) in that precision.
std::vector<BackendSlot> start_backends(const std::vector<std::string>& filter);
// The precision a twin backend's name asks for; nothing for any other name.
std::optional<twin::Precision> twin_backend_precision(const std::string& name);

struct PlannedCell {
  Language language;
  BackendSlot* backend;
  ShaderPath path;
};

struct CellGroup {
  const Case* c;
  const Variant* variant;
  std::string shape;
  std::vector<PlannedCell> cells;
  // A differential case's original: the cell whose render every cell of the group is
  // judged against, drawn whatever the filters select (its variant may be another one).
  std::optional<PlannedCell> reference_cell;
  const Variant* reference_variant = nullptr;
};

struct CellFilters {
  std::vector<std::string> variants, languages, shapes, backends, paths;
};

// The backends a run starts: the filter's (empty = vulkan, gl), plus the backend of every
// selected differential case's reference render, which is drawn even when filtered out.
std::vector<std::string> backends_to_start(const std::vector<Case>& cases, const std::vector<std::string>& filter);

std::vector<CellGroup> plan_cells(const std::vector<Case>& cases, std::vector<BackendSlot>& backends,
                                  const CellFilters& filters);

struct Shard {
  int index = 1;   // 1-based
  int count = 1;
};

// "I/N" with 1 <= I <= N.
Result<Shard> parse_shard(const std::string& text);

// The id its result will have (CellResult::id): case/variant/language/backend/path/shape.
std::string cell_id(const CellGroup& g, const PlannedCell& cell);

// Group g goes to shard (g mod N) + 1: every shard gets a spread of cases and shapes.
std::vector<CellGroup> select_shard(std::vector<CellGroup> groups, const Shard& shard);

}  // namespace shaderbed
