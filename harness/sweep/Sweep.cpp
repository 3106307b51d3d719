#include "sweep/Sweep.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <set>

#include <fmt/format.h>

#include "prt/ShCase.h"
#include "run/ReferenceKinds.h"
#include "run/Runner.h"
#include "plot/ParetoFront.h"
#include "scene/CaseSelection.h"
#include "scene/NameFilter.h"

namespace shaderbed {
namespace {

bool is_lut_axis(const std::string& name) { return name == "lut_size" || name == "lut_rows"; }

// Axes that choose how a scene is drawn rather than what the scene is.
bool is_implementation_axis(const std::string& name) { return is_lut_axis(name) || name == kTessellationAxis; }

// Whether drawing `variant` at another value of `axis` draws something different.
bool reads(const Variant& variant, const SweepAxis& axis) { return !is_lut_axis(axis.name) || !variant.lut.empty(); }

Result<void> check_axes(const Case& c, const std::vector<SweepAxis>& axes) {
  std::vector<std::string> scalars{kTessellationAxis};
  for (const auto& [name, values] : c.params)
    if (values.size() == 1) scalars.push_back(name);
  for (size_t i = 0; i < axes.size(); ++i) {
    const SweepAxis& axis = axes[i];
    if (std::find(scalars.begin(), scalars.end(), axis.name) == scalars.end())
      return fail(ErrorStage::options, fmt::format("--param {}: case '{}' has no scalar parameter of that name (it has: {})",
                                         axis.name, c.name, fmt::join(scalars, ", ")));
    for (size_t j = 0; j < i; ++j)
      if (axes[j].name == axis.name) return fail(ErrorStage::options, fmt::format("--param {} is given twice", axis.name));
    if (axis.name == kTessellationAxis && axis.values.front() < 4)
      return fail(ErrorStage::options, fmt::format("--param {}: at least 4 slices", axis.name));
    if (is_lut_axis(axis.name) && axis.values.front() < 2)
      return fail(ErrorStage::options, fmt::format("--param {}: a LUT needs at least 2 entries per axis", axis.name));
  }
  return {};
}

std::vector<std::string> default_languages(const Case& c) {
  std::vector<Language> present;
  for (const Variant& v : c.variants)
    for (const auto& [language, files] : v.shaders)
      if (std::find(present.begin(), present.end(), language) == present.end()) present.push_back(language);
  if (std::find(present.begin(), present.end(), Language::glsl) != present.end()) return {"glsl"};
  return present.empty() ? std::vector<std::string>{} : std::vector<std::string>{to_string(present.front())};
}

// Every combination of axis values, first axis slowest.
std::vector<std::vector<double>> combinations(const std::vector<SweepAxis>& axes) {
  std::vector<std::vector<double>> out{{}};
  for (const SweepAxis& axis : axes) {
    std::vector<std::vector<double>> next;
    for (const auto& prefix : out)
      for (double v : axis.values) {
        next.push_back(prefix);
        next.back().push_back(v);
      }
    out = std::move(next);
  }
  return out;
}

SweepPoint point_of(const CellResult& r, const std::map<std::string, double>& axis_values, const std::string& precision,
                    bool several_precisions) {
  SweepPoint p;
  p.axis_values = axis_values;
  p.cell = {{"variant", r.variant}, {"precision", precision}, {"language", r.language},
            {"backend", r.backend},  {"path", r.path},          {"shape", r.shape}};
  p.series = r.variant;
  if (several_precisions) p.series += " " + precision;
  std::vector<std::string> parts;
  for (const auto& [name, value] : axis_values) parts.push_back(fmt::format("{} {}", name, format_axis_value(value)));
  p.label = parts.empty() ? r.variant : fmt::format("{}", fmt::join(parts, ", "));
  p.status = r.status;
  p.message = r.message;
  p.rmse = r.metrics.rmse;
  p.max_abs = r.metrics.max_abs;
  if (r.sh && r.sh->render_vs_exact >= 0) {
    p.rmse = r.sh->rmse_vs_exact;
    p.max_abs = r.sh->render_vs_exact;
    p.precompute_ms = r.sh->precompute_ms;
    p.bytes_per_vertex = r.sh->bytes_per_vertex;
  }
  p.time_ms = r.gpu.wall.median;
  p.time_low_ms = r.gpu.wall.low;
  p.time_high_ms = r.gpu.wall.high;
  p.driver_clock_ms = r.gpu.device.median;
  if (auto b = r.time_ms.find("build"); b != r.time_ms.end()) p.build_ms = b->second;
  p.vertex_instructions = r.vertex_instructions;
  p.fragment_instructions = r.fragment_instructions;
  p.instructions = r.vertex_instructions + r.fragment_instructions;
  return p;
}

void mark_pareto_fronts(std::vector<SweepPoint>& points) {
  std::set<std::string> scenes;
  for (const SweepPoint& p : points) scenes.insert(p.scene);
  for (const std::string& scene : scenes) {
    std::vector<CostError> measured;
    std::vector<size_t> index;   // measured[i] is points[index[i]]
    for (size_t i = 0; i < points.size(); ++i)
      if (points[i].scene == scene && points[i].status != CellStatus::error) {
        // With its interval: points whose draw times are within noise are not ordered by speed.
        measured.push_back({points[i].time_ms, points[i].rmse, points[i].time_low_ms, points[i].time_high_ms});
        index.push_back(i);
      }
    for (size_t i : find_pareto_front(measured).front) points[index[i]].pareto = true;
  }
}

}  // namespace

Result<SweepResult> run_sweep(const SweepOptions& o) {
  // Counted before anything is loaded or drawn (and before the combinations are listed).
  const size_t precision_count = std::max<size_t>(1, o.precisions.size());
  size_t points = precision_count;
  std::vector<std::string> factors;
  for (const SweepAxis& a : o.axes) {
    const size_t n = std::max<size_t>(1, a.values.size());
    points = points > std::numeric_limits<size_t>::max() / n ? std::numeric_limits<size_t>::max() : points * n;
    factors.push_back(fmt::format("{} {}", n, a.name));
  }
  if (points > o.max_points)
    return fail(ErrorStage::sweep,
                fmt::format("the axes make {} points ({} x {} precision{}), more than the limit of {}: nothing drawn; "
                            "--max-points {} raises the limit if you mean it",
                            points, fmt::join(factors, " x "), precision_count, precision_count == 1 ? "" : "s",
                            o.max_points, points));
  const std::string dir = o.cases_dir.empty() ? default_cases_dir() : o.cases_dir;
  auto cases = load_selected_cases(dir, {o.case_name});
  if (!cases) return std::unexpected(cases.error());
  if (auto ok = complete_case(cases->front()); !ok) return std::unexpected(ok.error());
  const Case* c = &cases->front();
  if (auto ok = check_axes(*c, o.axes); !ok) return std::unexpected(ok.error());
  std::vector<std::string> variant_names;
  for (const Variant& v : c->variants) variant_names.push_back(v.name);
  if (auto ok = check_names(o.variants, variant_names, "variant"); !ok) return std::unexpected(ok.error());
  const std::vector<std::string> precisions = o.precisions.empty() ? std::vector<std::string>{"fp32"} : o.precisions;
  if (auto ok = check_names(precisions, {"fp32", "relaxed"}, "precision"); !ok) return std::unexpected(ok.error());

  RunOptions run;
  run.select.cases_dir = dir;
  run.select.cases = {o.case_name};
  run.select.languages = o.languages.empty() ? default_languages(*c) : o.languages;
  run.select.backends = o.backends.empty() ? std::vector<std::string>{"vulkan"} : o.backends;
  run.select.shapes = o.shapes.empty() ? std::vector<std::string>{"sphere"} : o.shapes;
  run.cell.size = o.size;
  run.cell.timing = o.timing;
  run.workers.jobs = 1;
  run.cell.per_pixel_reference = true;

  struct Step {
    std::vector<double> values;
    std::string precision;
    std::vector<std::string> variants;
  };
  std::vector<Step> steps;
  const auto all = combinations(o.axes);
  for (size_t k = 0; k < all.size(); ++k)
    for (const std::string& precision : precisions) {
      Step step{all[k], precision, {}};
      for (const Variant& v : c->variants) {
        if (!wanted(o.variants, v.name)) continue;
        const bool varies = std::any_of(o.axes.begin(), o.axes.end(), [&](const SweepAxis& a) { return reads(v, a); });
        if (k == 0 || varies) step.variants.push_back(v.name);
      }
      if (!step.variants.empty()) steps.push_back(std::move(step));
    }

  SweepResult result{o.case_name, o.axes, precisions, o.size, o.timing, {}, {}};
  const auto start = std::chrono::steady_clock::now();
  result.steps_planned = steps.size();
  for (size_t s = 0; s < steps.size(); ++s) {
    if (o.stop_requested)
      if (std::string signal = o.stop_requested(); !signal.empty()) {
        result.interrupted_by = std::move(signal);
        break;
      }
    const Step& step = steps[s];
    RunOptions point = run;
    point.select.variants = step.variants;
    point.cell.relaxed_precision = step.precision == "relaxed";
    std::vector<std::string> label;
    for (size_t a = 0; a < o.axes.size(); ++a) {
      const std::string value = format_axis_value(step.values[a]);
      label.push_back(o.axes[a].name + "=" + value);
      if (o.axes[a].name == kTessellationAxis) point.cell.mesh_slices = int(step.values[a]);
      else point.select.params.push_back(o.axes[a].name + "=" + value);
    }
    label.push_back(step.precision);
    if (o.on_step) o.on_step(s, steps.size(), fmt::format("{}", fmt::join(label, " ")));
    auto report = run_suite(point);
    if (!report) return std::unexpected(report.error());
    if (result.cells.results.empty()) result.cells.tools = report->tools;
    for (CellResult& r : report->results) {
      const Variant& v = *std::find_if(c->variants.begin(), c->variants.end(),
                                       [&](const Variant& x) { return x.name == r.variant; });
      std::map<std::string, double> values;
      std::vector<std::string> scene;
      for (size_t a = 0; a < o.axes.size(); ++a) {
        if (reads(v, o.axes[a])) values[o.axes[a].name] = step.values[a];
        if (!is_implementation_axis(o.axes[a].name) &&
            !(is_sh_model(c->model) && is_sh_approximation_parameter(o.axes[a].name)))
          scene.push_back(o.axes[a].name + "=" + format_axis_value(step.values[a]));
      }
      result.points.push_back(point_of(r, values, step.precision, precisions.size() > 1));
      result.points.back().scene = fmt::format("{}", fmt::join(scene, " "));
      // Cells of different points share ids; the HTML report tells them apart by variant name.
      std::vector<std::string> point_label;
      for (const auto& [name, value] : values) point_label.push_back(name + "=" + format_axis_value(value));
      point_label.push_back(step.precision);
      r.variant += fmt::format(" [{}]", fmt::join(point_label, " "));
      if (r.status == CellStatus::fail && v.mode == LightingMode::per_vertex) {
        // Expected: the sweep judges it against the per-pixel model, not its own.
        r.known_failure = true;
        r.known_reason = "a per-vertex variant judged against the per-pixel model: its error is what shading at "
                         "vertices loses";
      }
      result.cells.results.push_back(std::move(r));
    }
    result.steps_done = s + 1;
  }
  if (o.on_step) o.on_step(steps.size(), steps.size(), "");
  result.cells.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  // With more than one language, backend, path or shape the series name says which.
  std::set<std::string> cells;
  for (const SweepPoint& p : result.points)
    cells.insert(p.cell.at("language") + " " + p.cell.at("backend") + "/" + p.cell.at("path") + " " + p.cell.at("shape"));
  if (cells.size() > 1)
    for (SweepPoint& p : result.points)
      p.series += " " + p.cell.at("language") + " " + p.cell.at("backend") + "/" + p.cell.at("path") + " " +
                  p.cell.at("shape");
  mark_pareto_fronts(result.points);
  return result;
}

}  // namespace shaderbed
