#include "hard/HardRunner.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <span>

#include <fmt/format.h>

#include "backends/Backend.h"
#include "backends/VertexInputs.h"
#include "backends/twin/TwinRenderer.h"
#include "run/CaseUniforms.h"
#include "run/CellDraw.h"
#include "run/ProgramCache.h"
#include "run/CellPlan.h"
#include "run/ReferenceRender.h"
#include "run/ReferenceKinds.h"
#include "run/Runner.h"
#include "compare/ImageComparison.h"
#include "compare/ImageFiles.h"
#include "compile/Compiler.h"
#include "hard/Scenarios.h"
#include "hard/Slice.h"
#include "reference/ModelRegistry.h"
#include "reference/Reference.h"
#include "scene/CaseFile.h"
#include "scene/CaseSelection.h"
#include "scene/NameFilter.h"

namespace shaderbed::hard {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;
const std::vector<std::string> kBookVariants = {"vertex", "pixel"};
const std::string kRobustVariant = "pixel_robust";

// The double reference of one scenario, and how each pixel is judged.
struct ScenarioReference {
  int width = 0, height = 0;
  std::vector<double> rgba;
  std::vector<PixelJudgement> judgement;
};

bool point_light(const std::string& model) {
  const reference::ModelInfo* info = reference::find_model(model);
  return info && (info->light == reference::LightUse::point || info->light == reference::LightUse::spot);
}

// Within kConditioningMargin of N.L = 0, N.V = 0 or L = -V (or L undefined), where the
// rounding of one dot decides a branch.
bool ill_conditioned(const reference::Configuration& config) {
  const double length_l = glm::length(config.to_light);
  if (length_l == 0 || !std::isfinite(length_l)) return true;
  const glm::dvec3 n = glm::normalize(config.normal), l = config.to_light / length_l, v = glm::normalize(config.to_eye);
  return std::abs(glm::dot(n, l)) < kConditioningMargin || std::abs(glm::dot(n, v)) < kConditioningMargin ||
         glm::length(l + v) < kConditioningMargin;
}

// Whether a user's case lights with a point light: its shader binds light_position (in any
// space), or the case says so, or its model's light is one.
bool user_point_light(const Case& c) {
  for (const auto& [language, table] : c.bindings)
    for (const auto& [uniform, binding] : table)
      for (const BindingSource& source : binding.sources)
        if (source.name.starts_with("light_position")) return true;
  return c.light == CaseLight::point || (c.light == CaseLight::model_default && point_light(c.model));
}

// Per pixel the model at the configuration the GPU sees. A per-vertex variant shades the
// quad's corners and the pixel centre lies on the diagonal 0-2, so its colour there is
// the mean of those two corners' colours.
ScenarioReference slice_reference(const Slice& slice, const Case& c, const std::map<std::string, std::vector<double>>& params,
                                  LightingMode mode) {
  ScenarioReference r{slice.width, slice.height, std::vector<double>(slice.pixels.size() * 4, 0.0),
                      std::vector<PixelJudgement>(slice.pixels.size(), PixelJudgement::measured)};
  const bool point = point_light(c.model);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::map<std::string, std::vector<double>>> rows;   // the parameters of each row
  for (int y = 0; y < slice.height; ++y) rows.push_back(row_params(slice, y, params));
  for (size_t i = 0; i < slice.pixels.size(); ++i) {
    const auto& params = rows[i / size_t(slice.width)];
    const reference::Configuration config = pixel_configuration(slice, slice.pixels[i], point);
    std::expected<glm::dvec3, std::string> rgb;
    if (mode == LightingMode::per_pixel) {
      rgb = reference::evaluate(c.model, params, config);
    } else {
      const glm::dvec3 a(slice.mesh.vertices[i * 4].position), b(slice.mesh.vertices[i * 4 + 2].position);
      auto ca = reference::evaluate(c.model, params, pixel_configuration(slice, slice.pixels[i], point, &a));
      auto cb = reference::evaluate(c.model, params, pixel_configuration(slice, slice.pixels[i], point, &b));
      rgb = ca && cb ? std::expected<glm::dvec3, std::string>(0.5 * (*ca + *cb)) : std::unexpected(std::string("undefined"));
    }
    const glm::dvec3 value = rgb ? *rgb : glm::dvec3(nan);   // d = 0: no value exists
    r.rgba[i * 4 + 0] = value.x;
    r.rgba[i * 4 + 1] = value.y;
    r.rgba[i * 4 + 2] = value.z;
    r.rgba[i * 4 + 3] = 1;
    const double length_l = glm::length(config.to_light);
    if (!rgb || length_l == 0) {
      r.judgement[i] = PixelJudgement::undefined;
      continue;
    }
    if (ill_conditioned(config)) r.judgement[i] = PixelJudgement::finite_only;
  }
  return r;
}

// A half_angle slice, drawn a row at a time with that row's parameter value (a uniform
// cannot change within one draw), assembled into one image.
Result<RenderOutput> draw_by_rows(const Slice& slice, const NamedValues& values,
                                  const std::function<Result<RenderOutput>(const Mesh&, const NamedValues&)>& draw) {
  RenderOutput assembled;
  assembled.image = Image(slice.width, slice.height);
  for (int y = 0; y < slice.height; ++y) {
    NamedValues row = values;
    std::vector<double>& value = row[slice.spec.row_param];
    value.assign(std::max<size_t>(value.size(), 1), float(slice.row_values[size_t(y)]));
    auto out = draw(row_mesh(slice, y), row);
    if (!out) return std::unexpected(out.error());
    const size_t first = size_t(y) * slice.width, count = size_t(slice.width);
    std::copy_n(out->image.rgba.begin() + first * 4, count * 4, assembled.image.rgba.begin() + first * 4);
    std::copy_n(out->image.coverage.begin() + first, count, assembled.image.coverage.begin() + first);
  }
  return assembled;
}

ScenarioReference mesh_reference(const ReferenceImage& ref) {
  ScenarioReference r{ref.width, ref.height, ref.rgba, {}};
  for (PixelClass c : classify_pixels(ref))
    r.judgement.push_back(c == PixelClass::interior     ? PixelJudgement::measured
                          : c == PixelClass::silhouette ? PixelJudgement::finite_only
                                                        : PixelJudgement::skipped);
  return r;
}

Result<std::vector<Case>> select_cases(const HardOptions& o) {
  if (auto ok = check_names(o.backends, {"vulkan", "gl"}, "backend"); !ok) return std::unexpected(ok.error());
  if (auto ok = check_names(o.languages, {"glsl", "hlsl", "cg"}, "language"); !ok) return std::unexpected(ok.error());
  // A user case's scenarios depend on its parameters: an unknown name there selects nothing.
  if (o.user_cases.empty())
    if (auto ok = check_names(o.scenarios, scenario_names(), "scenario"); !ok) return std::unexpected(ok.error());
  if (o.size < 8 || o.size > 1024) return fail(ErrorStage::options, fmt::format("--size {} is outside 8..1024", o.size));
  if (o.cases.empty() && !o.user_cases.empty()) return std::vector<Case>{};
  auto cases = load_selected_cases(o.cases_dir.empty() ? default_cases_dir() : o.cases_dir, o.cases);
  if (!cases) return cases;
  for (Case& c : *cases)
    if (auto ok = complete_case(c); !ok) return std::unexpected(ok.error());
  return cases;
}

Image to_image(const ScenarioReference& r) {
  Image image(r.width, r.height);
  for (size_t i = 0; i < r.rgba.size(); ++i) image.rgba[i] = float(r.rgba[i]);
  for (size_t i = 0; i < r.judgement.size(); ++i) image.coverage[i] = r.judgement[i] != PixelJudgement::skipped;
  return image;
}

// Relative error per channel (the NumericalError definition), a mismatched non-finite as 1e30.
Image relative_error_image(const Image& render, const ScenarioReference& r, double floor) {
  Image out(r.width, r.height);
  for (size_t i = 0; i < r.judgement.size(); ++i) {
    out.coverage[i] = r.judgement[i] != PixelJudgement::skipped;
    for (int c = 0; c < 3; ++c) {
      const double e = relative_error(render.rgba[i * 4 + c], r.rgba[i * 4 + c], floor);
      out.rgba[i * 4 + c] = std::isfinite(e) ? float(e) : 1e30f;
    }
    out.rgba[i * 4 + 3] = 1;
  }
  return out;
}

// A half_angle slice's rows run from the broadest lobe to the sharpest: the value of its
// row parameter at the first row that goes wrong, or nullopt when none does.
std::optional<double> first_failing_row(const Slice& slice, const Image& image, const ScenarioReference& r) {
  const size_t w = size_t(slice.width);
  for (int y = 0; y < slice.height; ++y) {
    Image row(slice.width, 1);
    std::copy_n(image.rgba.begin() + y * w * 4, w * 4, row.rgba.begin());
    std::copy_n(image.coverage.begin() + y * w, w, row.coverage.begin());
    const NumericalError e = numerical_error(row, std::span(r.rgba).subspan(y * w * 4, w * 4),
                                             std::span(r.judgement).subspan(y * w, w));
    if (e.nonfinite_mismatch > 0 || e.max_relative > kRelativeTolerance) return slice.row_values[size_t(y)];
  }
  return std::nullopt;
}

class HardRunner {
 public:
  HardRunner(const HardOptions& o, std::vector<BackendSlot>& backends) : o_(o), backends_(backends) {}

  void run_case(const Case& c, HardReport& report) {
    std::vector<const Variant*> variants;
    for (const Variant& v : c.variants)
      if (std::find(kBookVariants.begin(), kBookVariants.end(), v.name) != kBookVariants.end() || v.name == kRobustVariant)
        variants.push_back(&v);
    for (Scenario& s : scenarios_for(c.model, o_.size)) {
      if (!wanted(o_.scenarios, s.name)) continue;
      if (!report.scenario_probes.contains(s.name)) {
        report.scenarios.push_back(s.name);
        report.scenario_probes[s.name] = s.probes;
      }
      if (o_.progress) o_.progress(fmt::format("{} / {}", c.name, s.name));
      Case scenario_case = c;
      for (const auto& [name, value] : s.params)
        if (scenario_case.params.contains(name)) scenario_case.params[name] = value;
      run_scenario(scenario_case, s, variants, report);
    }
  }

 void run_user_case(const Case& c, HardReport& report) {
    UserCaseTraits traits{.point_light = user_point_light(c), .reads_tangent = false};
    for (const Variant& v : c.variants)
      for (const auto& shader : v.shaders)
        if (auto program = program_for(c, v, shader.first); program)
          if (auto streams = attribute_streams_for((*program)->vertex.reflection.inputs,
                                                   c.attributes.contains(shader.first) ? &c.attributes.at(shader.first) : nullptr,
                                                   shader.first, nullptr))
            for (const AttributeStream& a : *streams)
              traits.reads_tangent |= a.attribute == VertexAttribute::tangent || a.attribute == VertexAttribute::binormal;
    for (Scenario& s : user_scenarios(c, traits)) {
      if (!wanted(o_.scenarios, s.name)) continue;
      const std::string key = c.name + "/" + s.name;
      report.scenarios.push_back(key);
      report.scenario_probes[key] = s.probes;
      if (o_.progress) o_.progress(fmt::format("{} / {}", c.name, s.name));
      Case scenario_case = c;
      for (const auto& [name, value] : s.params)
        if (scenario_case.params.contains(name)) scenario_case.params[name] = value;
      run_user_scenario(scenario_case, s, traits, report);
    }
  }

 private:
  // A user case's scenario: every variant and language drawn by the double twin (the
  // reference) and by each backend, the fp32 render against the twin.
  void run_user_scenario(const Case& c, const Scenario& s, const UserCaseTraits& traits, HardReport& report) {
    const Slice slice = make_slice(*s.slice, o_.size);
    NamedValues values = slice_scene_values(slice, c.ambient.value_or(glm::dvec3(0)));
    for (const auto& [name, value] : c.params) values.try_emplace(name, value);
    std::vector<PixelJudgement> judgement(slice.pixels.size(), PixelJudgement::measured);
    for (size_t i = 0; i < slice.pixels.size(); ++i)
      if (ill_conditioned(pixel_configuration(slice, slice.pixels[i], traits.point_light)))
        judgement[i] = PixelJudgement::finite_only;
    SceneSetup scene;
    scene.width = slice.width;
    scene.height = slice.height;
    const fs::path dir = o_.out_dir.empty() ? fs::path() : fs::path(o_.out_dir) / c.name / s.name;
    if (!dir.empty()) {
      std::error_code ignored;
      fs::create_directories(dir, ignored);
    }

    for (const Variant& v : c.variants)
      for (const auto& shader : v.shaders) {
        const Language language = shader.first;
        if (!wanted(o_.languages, to_string(language))) continue;
        // The reference: the shader's own twin in double.
        auto program = program_for(c, v, language);
        Result<ScenarioReference> reference = program ? Result<ScenarioReference>(ScenarioReference{})
                                                      : Result<ScenarioReference>(std::unexpected(program.error()));
        if (program) {
          auto drawn = draw_cell(twin_, {.c = c, .language = language, .path = ShaderPath::spirv, .program = **program,
                                         .mesh = slice.mesh, .scene = scene, .values = &values});
          if (!drawn) {
            reference = std::unexpected(drawn.error());
          } else {
            ScenarioReference& r = *reference;
            r.width = slice.width;
            r.height = slice.height;
            const Image& image = drawn->image;
            r.rgba = image.exact_rgba.empty() ? std::vector<double>(image.rgba.begin(), image.rgba.end()) : image.exact_rgba;
            r.judgement = judgement;
            for (size_t i = 0; i < r.judgement.size(); ++i)
              if (!image.coverage[i]) r.judgement[i] = PixelJudgement::skipped;
            if (!dir.empty()) (void)write_png((dir / (v.name + "-" + to_string(language) + ".twin.png")).string(), to_image(r));
          }
        }
        for (BackendSlot& b : backends_) {
          std::vector<ShaderPath> paths;
          if (b.backend) paths = (*b.backend)->paths(language);
          if (paths.empty()) paths = {ShaderPath::spirv};
          for (ShaderPath path : std::span(paths).first(o_.all_paths ? paths.size() : 1)) {
            HardRow row{.case_name = c.name, .scenario = s.name, .variant = v.name, .kind = "book",
                        .language = to_string(language), .backend = b.name, .path = to_string(path)};
            row.reference = "twin-double";
            const Result<ScenarioReference>* ref = &reference;
            auto ok = render_row(c, v, language, b, path, &slice, slice.mesh, values, ref, dir, row);
            if (!ok) {
              row.status = CellStatus::error;
              row.message = ok.error().to_string();
            } else {
              explain_worst_pixel(*reference, row);
            }
            report.rows.push_back(std::move(row));
          }
        }
      }
  }

  // The line that loses significance at the row's worst pixel, from the twin's last draw
  // (this scenario's, in this variant and language: the backends' draws do not touch it).
  void explain_worst_pixel(const ScenarioReference& reference, HardRow& row) {
    int worst = row.error.max_relative_pixel;
    if (row.error.nonfinite_mismatch > 0 && !row_mismatch_pixels_.empty()) worst = row_mismatch_pixels_.front();
    if (worst < 0) {
      row.loss_note = "no pixel measured";
      return;
    }
    row.worst_x = worst % reference.width;
    row.worst_y = worst / reference.width;
    auto loss = twin_.significance_loss(row.worst_x, row.worst_y);
    if (!loss) row.loss_note = "trace failed: " + loss.error().to_string();
    else if (!*loss) row.loss_note = "no instruction loses significance in the fp32 twin";
    else row.loss = std::move(**loss);
  }

  void run_scenario(const Case& c, Scenario& s, const std::vector<const Variant*>& variants, HardReport& report) {
    std::optional<Slice> slice;
    if (s.slice) slice = make_slice(*s.slice, o_.size);
    std::map<LightingMode, Result<ScenarioReference>> refs;   // per lighting mode
    const fs::path dir = o_.out_dir.empty() ? fs::path() : fs::path(o_.out_dir) / c.name / s.name;
    if (!dir.empty()) {
      std::error_code ignored;
      fs::create_directories(dir, ignored);
    }

    for (const Variant* v : variants) {
      const Result<ScenarioReference>* ref = nullptr;
      const Mesh* mesh = slice ? &slice->mesh : &s.mesh->mesh;
      if (!refs.contains(v->mode)) {
        if (slice) {
          refs.emplace(v->mode, slice_reference(*slice, c, c.params, v->mode));
        } else {
          s.mesh->scene.width = s.mesh->scene.height = o_.size;
          auto r = render_reference(s.mesh->mesh, s.mesh->scene, c, v->mode);
          refs.emplace(v->mode, r ? Result<ScenarioReference>(mesh_reference(*r))
                                  : Result<ScenarioReference>(std::unexpected(r.error())));
        }
      }
      ref = &refs.at(v->mode);
      if (*ref && !dir.empty()) (void)write_png((dir / (v->name + ".reference.png")).string(), to_image(**ref));
      NamedValues values = slice ? slice->uniforms : bindable_values(s.mesh->scene, c.params);
      if (slice)
        for (const auto& [name, value] : c.params) values.try_emplace(name, value);

      for (const auto& shader : v->shaders) {
        const Language language = shader.first;
        if (!wanted(o_.languages, to_string(language))) continue;
        for (BackendSlot& b : backends_) {
          std::vector<ShaderPath> paths;
          if (b.backend) paths = (*b.backend)->paths(language);
          if (paths.empty()) paths = {ShaderPath::spirv};   // the row reports why the backend cannot draw
          // The first path only, unless --all-paths: one row per backend by default.
          for (ShaderPath path : std::span(paths).first(o_.all_paths ? paths.size() : 1)) {
            HardRow row{.case_name = c.name, .scenario = s.name, .variant = v->name,
                        .kind = v->name == kRobustVariant ? "robust" : "book", .language = to_string(language),
                        .backend = b.name, .path = to_string(path)};
            auto ok = render_row(c, *v, language, b, path, slice ? &*slice : nullptr, *mesh, values, ref, dir, row);
            if (!ok) {
              row.status = CellStatus::error;
              row.message = ok.error().to_string();
            }
            report.rows.push_back(std::move(row));
          }
        }
      }
    }
  }

  Result<void> render_row(const Case& c, const Variant& v, Language language, BackendSlot& b,
                          ShaderPath path, const Slice* slice, const Mesh& mesh, const NamedValues& values, const Result<ScenarioReference>* ref,
                          const fs::path& dir, HardRow& row) {
    if (!b.backend) return std::unexpected(Error(b.backend.error()).in_backend(b.name));
    const CompiledProgram* program = nullptr;
    if (auto p = program_for(c, v, language); !p) return std::unexpected(p.error());
    else program = *p;
    if (!*ref) return std::unexpected(ref->error());
    const ScenarioReference& reference = **ref;

    // Drawn as `run` draws a cell (run/CellDraw.h): the case's textures, attribute map and
    // the program's render states too; a slice gives its own uniforms, row by row.
    SceneSetup scene;
    scene.width = reference.width;
    scene.height = reference.height;
    const auto draw = [&](const Mesh& m, const NamedValues& named) -> Result<RenderOutput> {
      auto drawn = draw_cell(**b.backend, {.c = c, .language = language, .path = path, .program = *program, .mesh = m,
                                           .scene = scene, .values = &named});
      if (!drawn) return std::unexpected(drawn.error());
      return RenderOutput{std::move(drawn->image), std::move(drawn->timings)};
    };
    auto rendered = slice && !slice->row_values.empty() ? draw_by_rows(*slice, values, draw) : draw(mesh, values);
    if (!rendered) return std::unexpected(rendered.error());

    row.width = reference.width;
    row.error = numerical_error(rendered->image, reference.rgba, reference.judgement);
    row_mismatch_pixels_.clear();
    if (row.error.nonfinite_mismatch > 0)
      for (size_t i = 0; i < reference.judgement.size(); ++i) {
        if (reference.judgement[i] == PixelJudgement::skipped || reference.judgement[i] == PixelJudgement::undefined) continue;
        bool render_finite = true, reference_finite = true;
        for (int k = 0; k < 3; ++k) {
          render_finite &= std::isfinite(rendered->image.rgba[i * 4 + size_t(k)]);
          reference_finite &= std::isfinite(reference.rgba[i * 4 + size_t(k)]);
        }
        if (render_finite != reference_finite) row_mismatch_pixels_.push_back(int(i));
      }
    const bool finite_ok = row.error.nonfinite_mismatch == 0;
    const bool error_ok = row.error.max_relative <= kRelativeTolerance;
    row.status = finite_ok && error_ok ? CellStatus::pass : CellStatus::fail;
    if (!finite_ok) row.message = fmt::format("{} pixels NaN/Inf on one side only", row.error.nonfinite_mismatch);
    if (!error_ok)
      row.message += fmt::format("{}max relative error {:.3g} > {:g}", row.message.empty() ? "" : "; ",
                                 row.error.max_relative, kRelativeTolerance);
    if (slice && !slice->row_values.empty() && row.status == CellStatus::fail)
      if (auto onset = first_failing_row(*slice, rendered->image, reference))
        row.message += fmt::format(", from {} = {:.3g} on", slice->spec.row_param, *onset);
    if (!dir.empty()) {
      const std::string stem = fmt::format("{}-{}-{}-{}", v.name, row.language, row.backend, row.path);
      for (auto written : {write_png((dir / (stem + ".png")).string(), rendered->image),
                           // Relative error: the pass tolerance shows as mid grey.
                           write_png((dir / (stem + ".error.png")).string(),
                                     relative_error_image(rendered->image, reference, row.error.floor),
                                     float(0.5 / kRelativeTolerance)),
                           write_png((dir / (stem + ".values.png")).string(), value_mask(rendered->image))})
        if (!written) return std::unexpected(written.error());
    }
    return {};
  }

  // The run's program cache: the same compiled stages, counts and errors as `run`'s cells.
  Result<const CompiledProgram*> program_for(const Case& c, const Variant& v, Language language) {
    const CachedProgram& entry = programs_.get(c, v, language);
    if (!entry.program) return std::unexpected(entry.program.error());
    return &*entry.program;
  }

  const HardOptions& o_;
  std::vector<BackendSlot>& backends_;
  TwinRenderer twin_{twin::Precision::exact};
  std::vector<int> row_mismatch_pixels_;   // of the last render_row: NaN/Inf on one side only
  ProgramCache programs_{ProgramOptions{.opengl = wanted(o_.backends, "gl")}};
};

void summarise(HardReport& report) {
  std::map<std::string, ModelSummary> by_case;
  std::vector<std::string> order;
  for (const HardRow& r : report.rows) {
    if (!by_case.contains(r.case_name)) order.push_back(r.case_name);
    ModelSummary& s = by_case[r.case_name];
    s.case_name = r.case_name;
    s.user = r.reference != "model";
    const bool robust = r.kind == "robust";
    s.has_robust |= robust;
    (robust ? s.robust_nonfinite : s.book_nonfinite) += r.error.render_nonfinite;
    (robust ? s.robust_mismatch : s.book_mismatch) += r.error.nonfinite_mismatch;
    double& rel = robust ? s.robust_max_relative : s.book_max_relative;
    rel = std::max(rel, r.error.max_relative);
    uint64_t& ulps = robust ? s.robust_max_ulps : s.book_max_ulps;
    ulps = std::max(ulps, r.error.max_ulps);
    if (r.status != CellStatus::pass) ++(robust ? s.robust_failed : s.book_failed);
  }
  for (const std::string& name : order) report.summaries.push_back(by_case.at(name));
}

}  // namespace

Result<HardReport> run_hard_cases(const HardOptions& o) {
  const auto start = Clock::now();
  auto cases = select_cases(o);
  if (!cases) return std::unexpected(cases.error());
  // Hard cases probe a model's numerics at chosen configurations: a case judged against a
  // render has no model to evaluate there.
  for (const Case& c : *cases)
    if (c.differential())
      return std::unexpected(Error{.message = "case '" + c.name + "' has no model (it is judged against a render): "
                                              "hard probes a lighting model's numerics",
                                   .file = c.path, .stage = ErrorStage::case_file});
  std::vector<BackendSlot> backends = start_backends(o.backends);

  HardReport report;
  report.size = o.size | 1;
  // The user's own cases, each file read as `run --case-file` reads it.
  std::vector<Case> user_cases;
  for (const std::string& path : o.user_cases) {
    auto c = load_case(path);
    if (!c) return std::unexpected(c.error());
    if (auto ok = complete_case(*c); !ok) return std::unexpected(ok.error());
    if (auto ok = check_binding_names(*c); !ok) return std::unexpected(ok.error());
    user_cases.push_back(std::move(*c));
  }
  HardRunner runner(o, backends);
  for (const Case& c : *cases) runner.run_case(c, report);
  for (const Case& c : user_cases) runner.run_user_case(c, report);
  if (report.rows.empty()) return fail(ErrorStage::options, "the filters select nothing to run");
  summarise(report);
  report.wall_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  return report;
}

}  // namespace shaderbed::hard
