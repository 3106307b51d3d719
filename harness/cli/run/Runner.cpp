#include "cli/run/Runner.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "backends/Backend.h"
#include "cli/run/CaseTextures.h"
#include "cli/run/CaseUniforms.h"
#include "cli/run/ParameterOverrides.h"
#include "cli/run/ReferenceRender.h"
#include "compare/ImageComparison.h"
#include "compare/ImageFiles.h"
#include "compile/Compiler.h"
#include "compile/ToolVersions.h"
#include "lut/LookupTexture.h"
#include "lut/LutTolerance.h"
#include "scene/CaseFile.h"
#include "scene/Primitives.h"

namespace shaderbed {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

bool wanted(const std::vector<std::string>& filter, const std::string& name) {
  return filter.empty() || std::find(filter.begin(), filter.end(), name) != filter.end();
}

Result<void> check_names(const std::vector<std::string>& given, const std::vector<std::string>& known, const char* what) {
  for (const std::string& g : given)
    if (std::find(known.begin(), known.end(), g) == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      return fail("options", fmt::format("unknown {} '{}' (known: {})", what, g, list));
    }
  return {};
}

Result<ProgramSource> load_program(Language language, const ShaderFiles& files, const std::string& case_path) {
  auto missing = [&](const std::string& file) {
    return std::unexpected(Error{.message = "shader file not found: " + file, .file = case_path, .line = files.line,
                                 .stage = "case"});
  };
  auto vs = load_shader_source(Stage::vertex, files.vertex);
  if (!vs) return missing(files.vertex);
  auto fs_ = load_shader_source(Stage::fragment, files.fragment);
  if (!fs_) return missing(files.fragment);
  return ProgramSource{language, std::move(*vs), std::move(*fs_)};
}

// One backend, created on first use; if it cannot start, every cell on it is an error.
struct BackendSlot {
  std::string name;
  Result<std::unique_ptr<Backend>> backend = fail("backend", "not started");
};

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
glm::dvec3 closest_point_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                     const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// The largest factor a Warn-style light puts in front of its LUT term on this shape:
// max(diffuse) * max(light_color) / d^2 at the surface point nearest the light (1 when
// the model has no light colour).
double light_scale(const Case& c, const Mesh& mesh, const SceneSetup& scene) {
  auto colour = c.params.find("light_color");
  if (colour == c.params.end()) return 1.0;
  double diffuse = 1;
  if (auto d = c.params.find("diffuse"); d != c.params.end())
    diffuse = *std::max_element(d->second.begin(), d->second.end());
  const double intensity = *std::max_element(colour->second.begin(), colour->second.end());
  const glm::dvec3 light = glm::inverse(scene.world) * glm::dvec4(scene.lights.position, 1.0);
  double nearest = INFINITY;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a = mesh.vertices[mesh.indices[t]].position, b = mesh.vertices[mesh.indices[t + 1]].position,
                     c3 = mesh.vertices[mesh.indices[t + 2]].position;
    nearest = std::min(nearest, glm::distance(light, closest_point_on_triangle(light, a, b, c3)));
  }
  return diffuse * intensity / (nearest * nearest);
}

}  // namespace

std::string default_cases_dir() {
  if (const char* root = std::getenv("SHADERBED_ROOT")) return (fs::path(root) / "shaders" / "cases").string();
  return (fs::path(SHADERBED_SOURCE_DIR) / "shaders" / "cases").string();
}

Result<RunReport> run_suite(const RunOptions& o) {
  const auto start = Clock::now();
  auto files = list_case_files(o.cases_dir.empty() ? default_cases_dir() : o.cases_dir);
  if (!files) return std::unexpected(files.error());
  std::vector<std::string> case_names;
  for (const std::string& f : *files) case_names.push_back(fs::path(f).stem().string());
  if (auto ok = check_names(o.cases, case_names, "case"); !ok) return std::unexpected(ok.error());
  // Only the selected cases are read, so one broken case file does not block the others.
  auto loaded = std::make_optional<std::vector<Case>>();
  for (const std::string& f : *files) {
    if (!wanted(o.cases, fs::path(f).stem().string())) continue;
    auto c = load_case(f);
    if (!c) return std::unexpected(c.error());
    loaded->push_back(std::move(*c));
  }
  if (auto ok = apply_parameter_overrides(o.params, o.cases, *loaded); !ok) return std::unexpected(ok.error());
  std::vector<std::string> variant_names;
  for (const Case& c : *loaded)
    for (const Variant& v : c.variants)
      if (std::find(variant_names.begin(), variant_names.end(), v.name) == variant_names.end())
        variant_names.push_back(v.name);
  if (auto ok = check_names(o.variants, variant_names, "variant"); !ok) return std::unexpected(ok.error());
  if (auto ok = check_names(o.backends, {"vulkan", "gl"}, "backend"); !ok) return std::unexpected(ok.error());
  if (auto ok = check_names(o.languages, {"glsl", "hlsl", "cg"}, "language"); !ok) return std::unexpected(ok.error());
  if (auto ok = check_names(o.shapes, shape_names(), "shape"); !ok) return std::unexpected(ok.error());
  if (o.size < 8 || o.size > 4096) return fail("options", fmt::format("--size {} is outside 8..4096", o.size));

  std::vector<BackendSlot> backends;
  for (const char* name : {"vulkan", "gl"})
    if (wanted(o.backends, name))
      backends.push_back({name, std::string(name) == "vulkan" ? make_vulkan_backend() : make_gl_backend()});

  RunReport report;
  report.out_dir = o.out_dir;
  const CompilerVersions versions = compiler_versions();
  report.tools = {versions.glslang, versions.spirv_tools, versions.spirv_cross, "", ""};
  for (const BackendSlot& b : backends) {
    const std::string v = b.backend ? (*b.backend)->driver_version() : "unavailable: " + b.backend.error().message;
    (b.name == "vulkan" ? report.tools.vulkan_driver : report.tools.gl_driver) = v;
  }

  SceneSetup scene;
  scene.width = scene.height = o.size;

  // Plan every cell first so progress can show done/total.
  struct Cell {
    const Case* c;
    const Variant* variant;
    Language language;
    std::string shape;
    BackendSlot* backend;
    ShaderPath path;
  };
  std::vector<Cell> cells;
  for (const Case& c : *loaded) {
    if (!wanted(o.cases, c.name)) continue;
    for (const Variant& v : c.variants) {
      if (!wanted(o.variants, v.name)) continue;
      for (const auto& [language, files] : v.shaders) {
        if (!wanted(o.languages, to_string(language))) continue;
        for (const std::string& shape : shape_names()) {
          if (!wanted(o.shapes, shape)) continue;
          for (BackendSlot& b : backends) {
            const std::vector<ShaderPath> paths =
                b.backend ? (*b.backend)->paths(language) : std::vector<ShaderPath>{ShaderPath::spirv};
            for (ShaderPath p : paths) cells.push_back({&c, &v, language, shape, &b, p});
          }
        }
      }
    }
  }
  if (cells.empty()) return fail("options", "the filters select no cells");

  std::map<std::string, Result<CompiledProgram>> programs;   // by case/variant/language
  std::map<std::string, double> compile_ms;
  std::map<std::string, Result<ReferenceImage>> references;  // by case/variant/shape
  std::map<std::string, double> reference_ms;
  std::map<std::string, Mesh> meshes;                        // by shape/tessellation
  std::map<std::string, Result<Texture>> luts;               // by case/variant
  std::map<std::string, Result<LutErrorBound>> lut_bounds;   // by case/variant/shape

  for (const Cell& cell : cells) {
    const Case& c = *cell.c;
    const std::string lang = to_string(cell.language);
    CellResult r{.case_name = c.name, .variant = cell.variant->name, .language = lang, .backend = cell.backend->name,
                 .path = to_string(cell.path), .shape = cell.shape};
    auto finish = [&](CellResult&& result) {
      report.results.push_back(std::move(result));
      if (o.on_cell) o.on_cell(report.results.size(), cells.size(), report.results.back());
    };
    auto error = [&](const Error& e) {
      r.status = "error";
      r.message = e.to_string();
      finish(std::move(r));
    };

    const std::string program_key = c.name + "/" + cell.variant->name + "/" + lang;
    if (!programs.contains(program_key)) {
      const auto t0 = Clock::now();
      auto source = load_program(cell.language, cell.variant->shaders.at(cell.language), c.path);
      programs.emplace(program_key, source ? compile_program(*source) : std::unexpected(source.error()));
      compile_ms[program_key] = ms_since(t0);
    }
    const Result<CompiledProgram>& program = programs.at(program_key);
    if (!program) {
      error(program.error());
      continue;
    }
    r.time_ms["compile"] = compile_ms[program_key];

    const std::string mesh_key = cell.shape + (c.tessellation == Tessellation::high ? "/high" : "/low");
    if (!meshes.contains(mesh_key)) meshes.emplace(mesh_key, *make_shape(cell.shape, c.tessellation));
    const Mesh& mesh = meshes.at(mesh_key);

    const std::string ref_key = c.name + "/" + cell.variant->name + "/" + mesh_key;
    if (!references.contains(ref_key)) {
      const auto t0 = Clock::now();
      references.emplace(ref_key, render_reference(mesh, scene, c, cell.variant->mode));
      reference_ms[ref_key] = ms_since(t0);
      if (references.at(ref_key) && !o.out_dir.empty()) {
        const ReferenceImage& ref = *references.at(ref_key);
        Image preview(ref.width, ref.height);
        for (size_t i = 0; i < ref.rgba.size(); ++i) preview.rgba[i] = float(ref.rgba[i]);
        preview.coverage = ref.coverage;
        const fs::path dir = fs::path(o.out_dir) / c.name / cell.variant->name / cell.shape;
        (void)write_exr((dir / "reference.exr").string(), ref.width, ref.height, preview.rgba);
        (void)write_png((dir / "reference.png").string(), preview);
      }
    }
    const Result<ReferenceImage>& reference = references.at(ref_key);
    if (!reference) {
      error(reference.error());
      continue;
    }
    r.time_ms["reference"] = reference_ms[ref_key];

    if (!cell.backend->backend) {
      error(Error(cell.backend->backend.error()).in_backend(cell.backend->name));
      continue;
    }
    const Texture* lut = nullptr;
    double interior_tolerance = c.interior.max_abs, silhouette_tolerance = c.silhouette.max_abs;
    if (!cell.variant->lut.empty()) {
      const std::string lut_key = c.name + "/" + cell.variant->name;
      if (!luts.contains(lut_key)) luts.emplace(lut_key, generate_lut(cell.variant->lut, c.params));
      const Result<Texture>& texture = luts.at(lut_key);
      if (!texture) {
        error(Error(texture.error()).in_file(c.path));
        continue;
      }
      lut = &*texture;
      const std::string bound_key = lut_key + "/" + mesh_key;
      if (!lut_bounds.contains(bound_key))
        lut_bounds.emplace(bound_key, c.lut->max_abs >= 0
                                          ? Result<LutErrorBound>(LutErrorBound{c.lut->max_abs, c.lut->max_abs, "given in the case"})
                                          : lut_error_bound(cell.variant->lut, c.params, *lut, light_scale(c, mesh, scene)));
      const Result<LutErrorBound>& bound = lut_bounds.at(bound_key);
      if (!bound) {
        error(Error(bound.error()).in_file(c.path));
        continue;
      }
      // The LUT's own error comes on top of the fp32 one, in each region.
      interior_tolerance += bound->max_abs;
      silhouette_tolerance += bound->band_max_abs;
      r.lut_bound = bound->max_abs;
      r.lut_derivation = bound->derivation;
    }
    r.interior_threshold = interior_tolerance;
    r.silhouette_threshold = silhouette_tolerance;

    auto bindings = c.bindings.find(cell.language);
    static const BindingTable no_bindings;
    const BindingTable& table = bindings == c.bindings.end() ? no_bindings : bindings->second;
    CaseUniforms uniforms(table, bindable_values(scene, c.params), c.path);
    CaseTextures textures(table, lut, c.path);
    auto rendered = (*cell.backend->backend)
                        ->render(DrawJob{*program, cell.path, mesh, uniforms, scene.width, scene.height, &textures});
    if (!rendered) {
      error(Error(rendered.error()).in_backend(cell.backend->name + "/" + to_string(cell.path)));
      continue;
    }
    r.time_ms["build"] = rendered->timings.build_ms;
    r.time_ms["draw"] = rendered->timings.draw_ms;
    r.time_ms["readback"] = rendered->timings.readback_ms;

    const auto t0 = Clock::now();
    const Comparison cmp = compare_images(rendered->image, *reference, {interior_tolerance, silhouette_tolerance});
    r.time_ms["compare"] = ms_since(t0);
    r.metrics = {cmp.interior.max_abs, cmp.interior.rmse, cmp.psnr,
                 cmp.interior.bad_pixels + cmp.silhouette.bad_pixels, cmp.nonfinite, cmp.coverage_mismatch,
                 cmp.silhouette.max_abs, cmp.interior.pixels, cmp.silhouette.pixels};
    r.status = cmp.pass ? "pass" : "fail";
    r.message = cmp.reason;

    if (!o.out_dir.empty()) {
      const fs::path dir = fs::path(o.out_dir) / c.name / cell.variant->name / cell.shape;
      const std::string stem = fmt::format("{}-{}-{}", lang, cell.backend->name, to_string(cell.path));
      r.artefacts.render_exr = (dir / (stem + ".exr")).string();
      r.artefacts.render_png = (dir / (stem + ".png")).string();
      r.artefacts.error_exr = (dir / (stem + ".error.exr")).string();
      r.artefacts.error_png = (dir / (stem + ".error.png")).string();
      r.artefacts.reference_png = (dir / "reference.png").string();
      bool written_all = true;
      for (auto written : {write_exr(r.artefacts.render_exr, scene.width, scene.height, rendered->image.rgba),
                           write_png(r.artefacts.render_png, rendered->image),
                           write_exr(r.artefacts.error_exr, scene.width, scene.height, cmp.error.rgba),
                           // Error heat map: the interior tolerance shows as mid grey.
                           write_png(r.artefacts.error_png, cmp.error,
                                     float(0.5 / std::max(interior_tolerance, 1e-12)))})
        if (written_all && !written) {
          written_all = false;
          error(written.error());
        }
      if (!written_all) continue;
    }
    finish(std::move(r));
  }
  report.wall_ms = ms_since(start);
  return report;
}

}  // namespace shaderbed
