#include "run/Runner.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "backends/MesaEnvironment.h"
#include "compile/CompileCache.h"
#include "compile/ToolVersions.h"
#include "core/BoundedFile.h"
#include "core/CacheSettings.h"
#include "core/ClosestName.h"
#include "core/Elapsed.h"
#include "core/Fnv1a.h"
#include "core/InstalledTree.h"
#include "core/WritablePath.h"
#include "prt/ShCase.h"
#include "run/CaseUniforms.h"
#include "run/ReferenceKinds.h"
#include "run/CellPlan.h"
#include "run/Expectations.h"
#include "run/GroupRunner.h"
#include "run/IsolatedRun.h"
#include "run/ParameterOverrides.h"
#include "run/StagedStoredImages.h"
#include "run/StoredImages.h"
#include "run/Toolchain.h"
#include "scene/CaseSelection.h"
#include "scene/NameFilter.h"
#include "scene/Primitives.h"

namespace shaderbed {
namespace fs = std::filesystem;
namespace {


// A shader file a selected cell needs and cannot find is one error before anything is
// drawn (exit 2), not an error in every cell of it; the languages not selected may miss theirs.
Result<void> check_shader_files(const std::vector<CellGroup>& groups) {
  for (const CellGroup& g : groups) {
    const auto check = [&](const Variant& v, Language language) -> Result<void> {
      const auto it = v.shaders.find(language);
      if (it == v.shaders.end()) return {};
      for (const auto& [stage, file] : {std::pair{"vertex", &it->second.vertex}, {"fragment", &it->second.fragment}})
        if (!file->empty() && !fs::exists(*file))
          return std::unexpected(Error{.message = fmt::format("variant '{}': the {} {} shader {} does not exist", v.name,
                                                              to_string(language), stage, *file),
                                       .file = g.c->path, .line = it->second.line, .stage = ErrorStage::case_file});
      return {};
    };
    for (const PlannedCell& cell : g.cells)
      if (auto ok = check(*g.variant, cell.language); !ok) return ok;
    if (g.reference_cell && g.reference_variant)
      if (auto ok = check(*g.reference_variant, g.reference_cell->language); !ok) return ok;
  }
  return {};
}

// Every file the planned cells read: their case files, the shaders of every language of
// their variants and originals, their textures, and the expectations.
std::vector<std::string> run_inputs(const SuitePlan& plan, const RunOptions& o) {
  std::vector<std::string> inputs{o.expectations};
  const auto add_variant = [&](const Variant* v) {
    if (!v) return;
    for (const auto& [language, files] : v->shaders) inputs.insert(inputs.end(), {files.vertex, files.fragment});
  };
  const auto add_textures = [&](const std::map<std::string, TextureBinding>& table) {
    for (const auto& [name, binding] : table) inputs.insert(inputs.end(), binding.files.begin(), binding.files.end());
  };
  for (const Case& c : plan.cases) {
    inputs.push_back(c.path);
    if (c.sh) inputs.push_back(c.sh->probe);
    add_textures(c.textures.common);
    for (const auto& [language, table] : c.textures.per_language) add_textures(table);
  }
  for (const CellGroup& g : plan.groups) {
    add_variant(g.variant);
    add_variant(g.reference_variant);
  }
  return inputs;
}

// Reads the selected case files, applies --param overrides and checks every name filter.
Result<std::vector<Case>> select_cases(const RunOptions& o) {
  const SuiteSelection& s = o.select;
  auto selected = load_selected_cases(s.cases_dir.empty() ? default_cases_dir() : s.cases_dir, s.cases);
  if (!selected) return std::unexpected(selected.error());
  std::vector<Case> cases = std::move(*selected);
  for (Case& c : cases)
    if (auto ok = complete_case(c); !ok) return std::unexpected(ok.error());
  if (auto ok = apply_parameter_overrides(s.params, s.cases, cases); !ok) return std::unexpected(ok.error());
  // An unknown model is bad input in the case file, not an error in every one of its cells.
  for (const Case& c : cases)
    if (!c.differential() && !is_reference_model(c.model)) {
      const std::vector<std::string> models = reference_model_names();
      const std::string near = closest_name(c.model, std::vector<std::string_view>(models.begin(), models.end()));
      const std::string known = near.empty() ? fmt::format("models: {}", fmt::join(models, ", "))
                                             : fmt::format("did you mean '{}'?", near);
      return std::unexpected(Error{.message = "unknown model '" + c.model + "' (" + known + ")", .file = c.path,
                                   .line = c.model_line, .stage = ErrorStage::case_file});
    }
  for (const Case& c : cases)
    if (!is_sh_model(c.model))
      if (auto ok = check_binding_names(c); !ok) return std::unexpected(ok.error());
  std::vector<std::string> variant_names;
  for (const Case& c : cases)
    for (const Variant& v : c.variants)
      if (std::find(variant_names.begin(), variant_names.end(), v.name) == variant_names.end())
        variant_names.push_back(v.name);
  if (auto ok = check_names(s.variants, variant_names, "variant"); !ok) return std::unexpected(ok.error());
  if (auto ok = check_names(s.backends, {"vulkan", "gl", "twin-double", "twin-float", "twin-half"}, "backend"); !ok)
    return std::unexpected(ok.error());
  if (auto ok = check_names(s.languages, {"glsl", "hlsl", "cg"}, "language"); !ok) return std::unexpected(ok.error());
  if (auto ok = check_names(s.paths, {"spirv", "glsl", "cross"}, "path"); !ok) return std::unexpected(ok.error());
  if (auto ok = check_names(s.shapes, shape_names(), "shape"); !ok) return std::unexpected(ok.error());
  const int size = o.cell.size;
  if (size < 8 || size > 4096) return fail(ErrorStage::options, fmt::format("--size {} is outside 8..4096", size));
  return cases;
}

// Runs the plan's groups on `o.workers.jobs` threads in this process, each worker with its own
// backends (a Vulkan device and a GL context serve one thread at a time). The first worker
// starts its backends before the others, and its drivers' versions are the report's.
std::vector<CellResult> run_in_process(const RunOptions& o, const SceneSetup& scene, SuitePlan& plan,
                                       ToolVersions& tools, int& workers_used) {
  const auto bundles = bundles_of(plan.groups);
  const int hardware = int(std::max(1u, std::thread::hardware_concurrency()));
  const size_t workers = std::min(bundles.size(), size_t(o.workers.jobs > 0 ? o.workers.jobs : hardware));
  workers_used = int(workers);
  std::vector<std::vector<BackendSlot>> own(workers);
  own[0] = start_backends(plan.backend_names);
  tools = toolchain(own[0]);
  auto stored = load_stored_references(o.cell.against_dir, o.cell.size, plan.cases, tools);
  if (!stored) return {};   // checked when planned; a folder removed since then runs nothing
  std::mutex mutex;   // guards next, results, o.on_cell
  size_t next = 0;
  std::vector<CellResult> results;
  const auto work = [&](std::vector<BackendSlot>& backends) {
    GroupRunner runner(cell_settings(o), scene, *stored, wanted(plan.backend_names, "gl"), o.on_step);
    for (;;) {
      size_t b;
      {
        const std::lock_guard lock(mutex);
        if (next == bundles.size()) return;
        b = next++;
      }
      for (size_t g : bundles[b])
        for (CellResult& r : runner.run(on_backends(plan.groups[g], plan, backends))) {
          const std::lock_guard lock(mutex);
          results.push_back(std::move(r));
          if (o.on_cell) o.on_cell(results.size(), plan.cells, results.back());
        }
    }
  };
  std::vector<std::jthread> threads;
  for (size_t w = 1; w < workers; ++w)
    threads.emplace_back([&, w] {
      own[w] = start_backends(plan.backend_names);
      work(own[w]);
    });
  work(own[0]);
  threads.clear();   // joins
  return results;
}

}  // namespace

std::string default_cases_dir() {
  fs::path root = SHADERBED_SOURCE_DIR;
  if (const char* env = std::getenv("SHADERBED_ROOT"); env != nullptr && *env != '\0') root = env;
  else if (fs::path installed = installed_data_dir(); !installed.empty()) root = installed;
  return (root / "shaders" / "cases").string();
}

void sort_results(RunReport& report) {
  std::stable_sort(report.results.begin(), report.results.end(),
                   [](const CellResult& a, const CellResult& b) { return a.id() < b.id(); });
}

std::vector<std::vector<size_t>> bundles_of(const std::vector<CellGroup>& groups) {
  std::vector<std::vector<size_t>> bundles;
  for (size_t g = 0; g < groups.size(); ++g) {
    const CellGroup& first = bundles.empty() ? groups[g] : groups[bundles.back().front()];
    if (bundles.empty() || first.c != groups[g].c || first.variant != groups[g].variant) bundles.emplace_back();
    bundles.back().push_back(g);
  }
  const auto cells = [&](const std::vector<size_t>& bundle) {
    size_t n = 0;
    for (size_t g : bundle) n += groups[g].cells.size();
    return n;
  };
  std::stable_sort(bundles.begin(), bundles.end(), [&](const auto& a, const auto& b) { return cells(a) > cells(b); });
  return bundles;
}

CellGroup on_backends(const CellGroup& g, const SuitePlan& plan, std::vector<BackendSlot>& backends) {
  CellGroup local = g;
  for (PlannedCell& cell : local.cells) cell.backend = &backends[size_t(cell.backend - plan.backends.data())];
  if (local.reference_cell)
    local.reference_cell->backend = &backends[size_t(local.reference_cell->backend - plan.backends.data())];
  return local;
}

Result<std::unique_ptr<SuitePlan>> plan_suite(const RunOptions& o) {
  auto plan = std::make_unique<SuitePlan>();
  auto cases = select_cases(o);
  if (!cases) return std::unexpected(cases.error());
  plan->cases = std::move(*cases);
  if (!o.expectations.empty()) {
    auto loaded = load_expectations(o.expectations);
    if (!loaded) return std::unexpected(loaded.error());
    plan->known = std::move(*loaded);
  }
  std::optional<Shard> shard;
  if (!o.select.shard.empty()) {
    auto parsed = parse_shard(o.select.shard);
    if (!parsed) return std::unexpected(parsed.error());
    shard = *parsed;
  }
  const SuiteSelection& s = o.select;
  plan->backend_names = backends_to_start(plan->cases, s.backends);
  for (const char* name : {"vulkan", "gl"})
    if (wanted(plan->backend_names, name)) plan->backends.push_back({name});
  for (const std::string& name : plan->backend_names)
    if (twin_backend_precision(name)) plan->backends.push_back({name});
  plan->groups = plan_cells(plan->cases, plan->backends, {s.variants, s.languages, s.shapes, s.backends, s.paths});
  if (plan->groups.empty()) return fail(ErrorStage::options, "the filters select no cells");
  if (shard) plan->groups = select_shard(std::move(plan->groups), *shard);
  for (const CellGroup& g : plan->groups) plan->cells += g.cells.size();
  // Stored runs are checked (folder, manifest, image size) before anything is drawn.
  if (auto stored = load_stored_references(o.cell.against_dir, o.cell.size, plan->cases, {}); !stored)
    return std::unexpected(stored.error());
  return plan;
}

namespace {

// Which run the results belong to: what decides the pixels and the verdicts (image size,
// mesh density, precision, reference, --param overrides, the compilers), never which cells
// were selected, so the jobs of a CI matrix (one --backend x --lang each) and the shards of
// a run share it. The case files' own text is compared per case (RunReport::case_digests).
std::string run_identity(const RunOptions& o) {
  const CellSettings& cell = o.cell;
  const CompilerVersions compilers = compiler_versions();
  const std::string text =
      fmt::format("size {} slices {} relaxed {} per-pixel {} against {}|params {}|{} {} {}", cell.size,
                  cell.mesh_slices, cell.relaxed_precision, cell.per_pixel_reference, cell.against_dir,
                  fmt::join(o.select.params, ","), compilers.glslang, compilers.spirv_tools, compilers.spirv_cross);
  return hex64(fnv1a64(text));
}

std::map<std::string, std::string> case_digests(const std::vector<Case>& cases) {
  std::map<std::string, std::string> digests;
  for (const Case& c : cases)
    digests[c.name] = hex64(fnv1a64(read_bounded_file(c.path, "case file", ErrorStage::case_file).value_or("")));
  return digests;
}

}  // namespace

Result<RunReport> run_suite(const RunOptions& o) {
  const auto start = Clock::now();
  const CompileCacheCounts compiles_before = compile_cache_counts();
  auto plan = plan_suite(o);
  if (!plan) return std::unexpected(plan.error());
  // The viewer plans a whole case and draws one language of it: only a run refuses a
  // selected cell's missing shader up front.
  if (auto ok = check_shader_files((*plan)->groups); !ok) return std::unexpected(ok.error());
  const std::vector<std::string> inputs = run_inputs(**plan, o);
  for (const auto& [path, option] : o.report_files)
    if (auto ok = check_not_an_input(path, option, inputs); !ok) return std::unexpected(ok.error());
  // A run never writes into the stored images that judge it, and replaces a stored set
  // only as a whole, after it has finished: until then its cells (in the workers too)
  // save their images into the staging folder, as if it were the --save-images folder.
  RunOptions staged_options = o;
  std::optional<StagedStoredImages> staged;
  if (auto ok = check_stored_folders(o.cell.out_dir, o.cell.save_images_dir,
                                     stored_reference_dirs(o.cell.against_dir, (*plan)->cases));
      !ok)
    return std::unexpected(ok.error());
  if (!o.cell.save_images_dir.empty()) {
    auto begun = StagedStoredImages::begin(o.cell.save_images_dir, o.cell.size);
    if (!begun) return std::unexpected(begun.error());
    staged.emplace(std::move(*begun));
    staged_options.cell.save_images_dir = staged->staging_dir();
  }

  RunReport report;
  report.run_id = run_identity(o);
  report.case_digests = case_digests((*plan)->cases);
  report.out_dir = o.cell.out_dir;
  if (!o.cell.out_dir.empty()) report.keep_images = o.cell.keep_images;
  report.shard = o.select.shard;
  SceneSetup scene;
  scene.width = scene.height = o.cell.size;
  CompileCacheCounts compiles;
  if (o.workers.worker_binary.empty()) {
    report.results = run_in_process(staged_options, scene, **plan, report.tools, report.workers);
    compiles = compile_cache_counts() - compiles_before;
  } else {
    isolate_mesa_shader_cache();   // as the workers' drivers will see it (and as the report says)
    auto isolated = run_isolated(staged_options, **plan);
    if (!isolated) return std::unexpected(isolated.error());
    report.results = std::move(isolated->results);
    report.tools = isolated->tools;
    report.workers = isolated->workers;
    report.interruption = isolated->interruption;
    compiles = isolated->compiles;
  }
  apply_expectations((*plan)->known, report);
  sort_results(report);
  const CacheSettings caches = cache_settings();
  const MesaShaderCacheState mesa_cache = mesa_shader_cache_state();
  report.cache = CacheUse{mesa_cache.enabled, mesa_cache.dir, caches.compile_enabled(),
                          caches.compile_enabled() ? caches.compile_dir() : "", compiles.hits(), compiles.misses(),
                          compiles.memory_hits};
  report.wall_ms = ms_since(start);
  if (staged) {
    if (report.interruption) {
      // An interrupted run's images go with its staging folder: the set stays as it was.
      for (CellResult& r : report.results) r.artefacts.stored_exr.clear();
    } else if (auto ok = staged->commit(report); !ok) {
      // The set stays as it was, and the run keeps its verdicts: each cell says its image
      // was not saved, and the run why.
      report.stored_images_lost = ok.error().to_string();
      for (CellResult& r : report.results)
        if (!r.artefacts.stored_exr.empty()) {
          r.artefacts.stored_exr.clear();
          r.warnings.push_back("stored image not saved: the set in " + o.cell.save_images_dir + " is as it was");
        }
    }
  }
  return report;
}

}  // namespace shaderbed
