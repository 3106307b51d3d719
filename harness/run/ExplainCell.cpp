#include "run/ExplainCell.h"

#include <fmt/format.h>

#include "run/GroupRunner.h"
#include "run/Runner.h"
#include "run/StoredImages.h"
#include "run/Toolchain.h"

namespace shaderbed {

Result<ExplainedCell> explain_cell(RunOptions options, const std::string& cell, std::optional<twin::PixelAt> pixel) {
  std::vector<std::string> parts;
  for (size_t at = 0;;) {
    const size_t slash = cell.find('/', at);
    parts.push_back(cell.substr(at, slash == std::string::npos ? std::string::npos : slash - at));
    if (slash == std::string::npos) break;
    at = slash + 1;
  }
  if (parts.size() == 6) parts.erase(parts.begin());   // the case's name, named already
  if (parts.size() != 5 || std::ranges::any_of(parts, [](const std::string& p) { return p.empty(); }))
    return fail(ErrorStage::options, fmt::format("--cell '{}': expected variant/language/backend/path/shape, e.g. "
                                                 "port/glsl/vulkan/spirv/sphere (as the failure list and the JSON name cells)",
                                                 cell));
  const std::string &variant = parts[0], &language = parts[1], &backend = parts[2], &path = parts[3], &shape = parts[4];
  options.select.variants = {variant};
  options.select.languages = {language};
  options.select.backends = {backend};
  options.select.shapes = {shape};
  options.cell.timing = {.warmup = 0, .runs = 0};
  auto plan = plan_suite(options);
  if (!plan) return std::unexpected(plan.error());
  SuitePlan& p = **plan;
  std::vector<BackendSlot> backends = start_backends(p.backend_names);
  for (const CellGroup& g : p.groups)
    for (const PlannedCell& c : g.cells) {
      if (to_string(c.path) != path) continue;
      const auto stored = load_stored_references(options.cell.against_dir, options.cell.size, p.cases, toolchain(backends));
      if (!stored) return std::unexpected(stored.error());
      SceneSetup scene;
      scene.width = scene.height = options.cell.size;
      GroupRunner runner(cell_settings(options), scene, *stored, backend == "gl");
      const std::string id = g.c->name + "/" + variant + "/" + language + "/" + backend + "/" + path + "/" + shape;
      runner.request_explanation(id, pixel);
      for (CellResult& r : runner.run(on_backends(g, p, backends))) {
        if (r.id() != id) continue;
        auto explained = runner.take_explanation();
        if (!explained)
          return fail(ErrorStage::twin, fmt::format("{} was not drawn ({}): nothing to explain", id,
                                                    r.message.empty() ? to_string(r.status) : r.message));
        if (!*explained) return std::unexpected(explained->error());
        return ExplainedCell{std::move(r), std::move(**explained)};
      }
    }
  return fail(ErrorStage::options, fmt::format("the case has no cell {} (its paths on {} are not '{}'?)", cell, backend, path));
}

}  // namespace shaderbed
