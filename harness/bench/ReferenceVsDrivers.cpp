#include "bench/ReferenceVsDrivers.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include <fmt/format.h>

#include "run/ReferenceRender.h"
#include "run/Runner.h"
#include "scene/CaseFile.h"
#include "scene/Primitives.h"
#include "timing/MedianInterval.h"

namespace shaderbed::bench {
namespace fs = std::filesystem;
namespace {

TimingInterval interval_of(const std::vector<double>& ms) {
  const MedianInterval m = median_interval(ms);
  return {m.median, m.low, m.high, m.level};
}

// What the reference renders for the cell: its case (as the runner reads it, without
// --param overrides), variant and mesh.
struct ReferenceInputs {
  Case c;
  LightingMode mode = LightingMode::per_pixel;
  Mesh mesh;
};

Result<ReferenceInputs> reference_inputs(const ComparedCell& cell, const std::string& cases_dir) {
  const std::string dir = cases_dir.empty() ? default_cases_dir() : cases_dir;
  const fs::path file = fs::path(dir) / (cell.case_name + ".toml");
  if (!fs::exists(file))
    return fail(ErrorStage::options, fmt::format("--compare {}: no case file {}", cell.label(), file.string()));
  auto c = load_case(file.string());
  if (!c) return std::unexpected(c.error());
  const auto variant = std::ranges::find(c->variants, cell.variant, &Variant::name);
  if (variant == c->variants.end())
    return fail(ErrorStage::options, fmt::format("--compare {}: case {} has no variant {}", cell.label(), cell.case_name,
                                       cell.variant));
  std::optional<Mesh> mesh = make_shape(cell.shape, c->tessellation);
  if (!mesh) return fail(ErrorStage::options, fmt::format("--compare {}: unknown shape {}", cell.label(), cell.shape));
  const LightingMode mode = variant->mode;
  return ReferenceInputs{std::move(*c), mode, std::move(*mesh)};
}

// The reference render of the cell, once untimed (first touches of memory), then `runs`
// timed.
Result<TimingInterval> time_reference(const ComparedCell& cell, const SpeedComparisonOptions& o) {
  auto in = reference_inputs(cell, o.cases_dir);
  if (!in) return std::unexpected(in.error());
  SceneSetup scene;
  scene.width = scene.height = o.size;
  std::vector<double> ms;
  for (int i = 0; i <= o.runs; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    const Result<ReferenceImage> image = render_reference(in->mesh, scene, in->c, in->mode);
    const double elapsed = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (!image) return std::unexpected(image.error());
    if (i > 0) ms.push_back(elapsed);
  }
  return interval_of(ms);
}

}  // namespace

Result<ComparedCell> parse_compared_cell(const std::string& text) {
  const size_t a = text.find('/');
  const size_t b = a == std::string::npos ? a : text.find('/', a + 1);
  if (b == std::string::npos || text.find('/', b + 1) != std::string::npos || a == 0 || b == a + 1 ||
      b + 1 == text.size())
    return fail(ErrorStage::options, fmt::format("'{}' is not case/variant/shape (e.g. phong/pixel/sphere)", text));
  return ComparedCell{text.substr(0, a), text.substr(a + 1, b - a - 1), text.substr(b + 1)};
}

Result<void> check_compared_cell(const ComparedCell& cell, const std::string& cases_dir) {
  auto in = reference_inputs(cell, cases_dir);
  if (!in) return std::unexpected(in.error());
  return {};
}

Result<ReferenceVsDrivers> time_reference_against_drivers(const ComparedCell& cell,
                                                          const SpeedComparisonOptions& o) {
  // One worker, so the draws have the cores to themselves as the reference does.
  RunOptions run;
  run.select.cases_dir = o.cases_dir;
  run.select.cases = {cell.case_name};
  run.select.variants = {cell.variant};
  run.select.shapes = {cell.shape};
  run.select.languages = {o.language};
  // The shader's double twin beside the drivers: its timed repeats run on one thread.
  run.select.backends = {"vulkan", "gl", "twin-double"};
  run.cell.size = o.size;
  run.workers.jobs = 1;
  run.cell.timing = {.warmup = 1, .runs = o.runs};
  auto report = run_suite(run);
  if (!report) return std::unexpected(report.error());

  auto reference = time_reference(cell, o);
  if (!reference) return std::unexpected(reference.error());

  ReferenceVsDrivers out{cell, o.size, *reference, o.runs, {}};
  for (const CellResult& r : report->results) {
    if (r.status == CellStatus::error)
      return fail(ErrorStage::bench, fmt::format("{} could not be drawn: {}", r.id(), r.message));
    const char* driver = r.backend == "vulkan" ? "lavapipe" : r.backend == "gl" ? "llvmpipe" : "twin, 1 thread";
    DriverDraw d{r.backend, r.path, r.language, driver, r.gpu.wall, 0};
    if (d.wall.median > 0) d.reference_ratio = reference->median / d.wall.median;
    out.draws.push_back(std::move(d));
  }
  // lavapipe first, then llvmpipe's paths in the runner's order, the twin last.
  std::ranges::stable_sort(out.draws, {}, [](const DriverDraw& d) { return d.backend == "vulkan" ? 0 : d.backend == "gl" ? 1 : 2; });
  const auto lavapipe = std::ranges::find(out.draws, std::string("vulkan"), &DriverDraw::backend);
  const auto twin = std::ranges::find(out.draws, std::string("twin-double"), &DriverDraw::backend);
  if (lavapipe != out.draws.end() && twin != out.draws.end() && lavapipe->wall.median > 0)
    out.twin_of_lavapipe = twin->wall.median / lavapipe->wall.median;
  return out;
}

}  // namespace shaderbed::bench
