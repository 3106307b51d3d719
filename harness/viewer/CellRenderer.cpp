#include "viewer/CellRenderer.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/CacheSettings.h"
#include "core/Elapsed.h"
#include "lut/LookupTexture.h"
#include "lut/LutTolerance.h"
#include "run/CaseTextures.h"
#include "run/CaseUniforms.h"
#include "run/LutScale.h"
#include "run/ReferenceRender.h"
#include "scene/Primitives.h"
#include "scene/ProjectedArea.h"
#include "viewer/CompileProbe.h"
#include "viewer/SplitView.h"

namespace shaderbed::viewer {
namespace {


const Variant* find_variant(const Case& c, const std::string& name) {
  const auto it = std::ranges::find(c.variants, name, &Variant::name);
  return it == c.variants.end() ? nullptr : &*it;
}

std::optional<ShaderPath> parse_path(const std::string& text) {
  for (ShaderPath p : {ShaderPath::spirv, ShaderPath::native_glsl, ShaderPath::cross_glsl})
    if (text == to_string(p)) return p;
  return std::nullopt;
}

ReferenceImage as_reference(const Image& image) {
  return {image.width, image.height, std::vector<double>(image.rgba.begin(), image.rgba.end()), image.coverage};
}

// The Cg and GLSL frameworks' "OpenGL shading": fixed-function Gouraud, i.e. Lambert
// evaluated at the vertices and interpolated, here by the reference's own rasteriser.
Case gouraud_case(const Case& c) {
  Case g = c;
  g.model = "lambert";
  g.reference_render.reset();
  g.reference_images.clear();
  const auto diffuse = c.params.find("diffuse");
  g.params = {{"diffuse", diffuse != c.params.end() && diffuse->second.size() == 3 ? diffuse->second
                                                                                    : std::vector<double>{1, 1, 1}}};
  return g;
}

}  // namespace

CellRenderer::CellRenderer(std::string probe_binary)
    : probe_(std::move(probe_binary)), programs_(std::make_unique<ProgramCache>(ProgramOptions{.opengl = true})) {}

CellRenderer::~CellRenderer() = default;

Result<Backend*> CellRenderer::backend(const std::string& name) {
  auto it = backends_.find(name);
  if (it == backends_.end())
    it = backends_.emplace(name, name == "vulkan" ? make_vulkan_backend() : make_gl_backend()).first;
  if (!it->second) return std::unexpected(Error(it->second.error()).in_backend(name));
  return it->second->get();
}

Result<const Texture*> CellRenderer::lut_of(const Case& c, const Variant& variant) {
  if (variant.lut.empty()) return nullptr;
  std::string key = c.name + "/" + variant.name;
  for (const auto& [name, values] : c.params) {
    key += " " + name;
    for (double v : values) key += fmt::format(" {:a}", v);
  }
  auto it = luts_.find(key);
  if (it == luts_.end()) it = luts_.emplace(key, generate_lut(variant.lut, c.params)).first;
  if (!it->second) return std::unexpected(Error(it->second.error()).in_file(c.path));
  return &*it->second;
}

// As the runner's draw_cell (run/GroupRunner.cpp): the program, the case's uniforms and
// textures for the language, the program's render state, the case's vertex attributes.
Result<CellRenderer::Drawn> CellRenderer::draw_program(const Case& c, const Variant& variant, Language language,
                                                       const std::string& backend_name, ShaderPath path,
                                                       const Mesh& mesh, const SceneSetup& scene, bool wireframe,
                                                       const Texture* lut, const ShPrepared* sh) {
  const std::string key = c.name + "/" + variant.name + "/" + to_string(language);
  auto device = backend(backend_name);   // first, so it starts while the probe compiles
  if (!device) return std::unexpected(device.error());
  if (!probed_.contains(key)) {
    if (auto ok = probe_.compile(c, variant, language); !ok) return std::unexpected(ok.error());
    probed_.insert(key);
  }
  const CachedProgram& compiled = programs_->get(c, variant, language);
  if (!compiled.program) return std::unexpected(compiled.program.error());

  static const BindingTable no_bindings;
  const auto bindings = c.bindings.find(language);
  const BindingTable& table = bindings == c.bindings.end() ? no_bindings : bindings->second;
  NamedValues values = bindable_values(scene, c);
  if (sh) values.insert(sh->uniforms.begin(), sh->uniforms.end());
  CaseUniforms uniforms(table, std::move(values), c.path);
  if (auto bound = uniforms.check_all_bound(*compiled.program); !bound) return std::unexpected(bound.error());
  CaseTextures textures(table, c.textures.for_language(language), lut, c.path, &compiled.program->sampler_settings,
                        sh ? &sh->textures : nullptr);
  if (auto ok = textures.check(*compiled.program); !ok) return std::unexpected(ok.error());
  DrawJob job{*compiled.program, path, mesh, uniforms, scene.width, scene.height, &textures, {.warmup = 0, .runs = 0}};
  job.render_state = compiled.program->render_state;
  if (wireframe) job.render_state.fill = FillMode::wireframe;
  const auto attributes = c.attributes.find(language);
  if (attributes != c.attributes.end()) job.attributes = &attributes->second;
  auto rendered = (*device)->render(job);
  if (!rendered) return std::unexpected(Error(rendered.error()).in_backend(backend_name + "/" + to_string(path)));
  return Drawn{std::move(rendered->image), rendered->timings.draw_ms + rendered->timings.readback_ms};
}

Result<const ShPrepared*> CellRenderer::sh_of(const Case& c, const std::string& mesh_key, const SceneSetup& scene) {
  std::string key = c.path + "|" + mesh_key + "|" + fmt::format("{},{},{}", scene.lights.direction.x,
                                                                 scene.lights.direction.y, scene.lights.direction.z);
  for (const auto& [name, values] : c.params) key += fmt::format("|{}={}", name, fmt::join(values, ","));
  if (!sh_ || key != sh_key_) {
    const std::string root = cache_settings().root;
    sh_ = prepare_sh(c, meshes_.at(mesh_key), scene, root.empty() ? std::filesystem::path() : std::filesystem::path(root) / "sh");
    sh_key_ = key;
  }
  if (!*sh_) return std::unexpected((*sh_).error());
  return &**sh_;
}

Frame CellRenderer::draw(const FrameRequest& request) {
  const auto t0 = Clock::now();
  Frame frame;
  frame.generation = request.generation;
  frame.state = request.state;
  const ViewerState& s = request.state;
  if (request.sources_changed) {
    programs_ = std::make_unique<ProgramCache>(ProgramOptions{.opengl = true});
    probed_.clear();
    luts_.clear();
  }
  probe_.prepare();   // its start-up overlaps the backend's, on the first frame
  Case c = with_parameters(*request.c, s);
  apply_sh_defaults(c);
  const auto finish = [&](Frame& f) -> Frame {
    f.frame_ms = ms_since(t0);
    return std::move(f);
  };
  const auto failed = [&](Error e) {
    frame.verdict = "error";
    frame.detail = e.to_string();
    frame.problem = std::move(e);
    return finish(frame);
  };
  const Variant* variant = find_variant(c, s.variant_name());
  if (!variant) return failed(Error{.message = "no variant '" + s.variant_name() + "'", .file = c.path, .stage = "case"});

  const std::string mesh_key = s.shape_name() + (c.tessellation == Tessellation::high ? "/high" : "/low");
  if (!meshes_.contains(mesh_key)) {
    auto mesh = make_shape(s.shape_name(), c.tessellation);
    if (!mesh) return failed(Error{.message = "unknown shape '" + s.shape_name() + "'", .stage = "options"});
    meshes_.emplace(mesh_key, std::move(*mesh));
  }
  const SceneSetup scene = scene_of(s, request.size);
  // An SH case draws the shape with its transfer streams, uniforms and textures (harness/prt).
  const ShPrepared* sh = nullptr;
  if (is_sh_model(c.model)) {
    if (request.sources_changed) sh_.reset();
    auto prepared = sh_of(c, mesh_key, scene);
    if (!prepared) return failed(prepared.error());
    sh = *prepared;
  }
  const Mesh& mesh = sh ? sh->mesh : meshes_.at(mesh_key);

  // The thresholds, widened for a LUT variant by its bound over what this shape shows.
  auto lut = lut_of(c, *variant);
  if (!lut) return failed(lut.error());
  ComparisonThresholds thresholds{c.interior.max_abs, c.silhouette.max_abs, c.interior.max_rel, c.silhouette.max_rel};
  if (*lut) {
    Result<LutErrorBound> bound = LutErrorBound{};
    if (c.lut && c.lut->max_abs >= 0) {
      bound = LutErrorBound{c.lut->max_abs, c.lut->max_abs, "given in the case"};
    } else {
      const Result<LutDomain> domain = lut_domain(c, mesh, scene, s.shape_name());
      bound = domain ? lut_error_bound(variant->lut, c.params, **lut, *domain)
                     : Result<LutErrorBound>(std::unexpected(domain.error()));
    }
    if (!bound) return failed(Error(bound.error()).in_file(c.path));
    thresholds.interior_max_abs += bound->max_abs;
    thresholds.silhouette_max_abs += bound->band_max_abs;
  }
  frame.interior_threshold = thresholds.interior_max_abs;

  // The image: the shader's (also in Gouraud mode with wireframe: its lines are the mask).
  std::optional<Drawn> shader;
  if (!s.gouraud || s.wireframe) {
    auto drawn = draw_program(c, *variant, s.language, s.backend, s.path, mesh, scene, s.wireframe, *lut, sh);
    if (!drawn) return failed(drawn.error());
    frame.draw_ms = drawn->draw_ms;
    shader = std::move(*drawn);
  }
  if (s.gouraud) {
    auto gouraud = render_reference(mesh, scene, gouraud_case(c), LightingMode::per_vertex);
    if (!gouraud) return failed(gouraud.error());
    Image image = reference_as_image(*gouraud);
    if (shader)   // the wireframe's lines, lit by the Gouraud light
      for (size_t i = 0; i < image.coverage.size(); ++i)
        if (!shader->image.coverage[i]) image.coverage[i] = 0;
    frame.render = std::move(image);
  } else {
    frame.render = std::move(shader->image);
  }

  // The reference: the model in double, or a differential case's original drawn alike.
  if (!c.reference_images.empty()) {
    frame.reference_problem = "the case's reference is stored images (" + c.reference_images +
                              "): the viewer draws only model and original references";
  } else if (sh) {   // the truncated SH in double, as run judges it
    auto reference = render_reference(mesh, scene, c, variant->mode, *sh->truncated);
    if (reference) frame.reference = std::move(*reference);
    else frame.reference_problem = reference.error().to_string();
  } else if (!c.differential()) {
    auto reference = render_reference(mesh, scene, c, variant->mode);
    if (reference) frame.reference = std::move(*reference);
    else frame.reference_problem = reference.error().to_string();
  } else if (c.reference_render) {
    const RenderReference& r = *c.reference_render;
    const Variant* original = r.variant.empty() ? variant : find_variant(c, r.variant);
    const auto path = parse_path(r.path);
    if (!original || !original->shaders.contains(r.language) || !path) {
      frame.reference_problem = fmt::format("the original ({} {}/{}) is not in the case", to_string(r.language),
                                            r.backend, r.path);
    } else {
      auto lut_original = lut_of(c, *original);
      auto drawn = lut_original ? draw_program(c, *original, r.language, r.backend, *path, mesh, scene, false, *lut_original)
                                : Result<Drawn>(std::unexpected(lut_original.error()));
      if (drawn) frame.reference = as_reference(drawn->image);
      else frame.reference_problem = "the original could not be drawn: " + drawn.error().to_string();
    }
  }

  if (!frame.reference) {
    frame.verdict = "not judged";
    frame.detail = frame.reference_problem;
    return finish(frame);
  }
  const glm::dmat4 clip_from_object =
      projection_matrix(scene.camera, double(scene.width) / scene.height) * view_matrix(scene.camera) * scene.world;
  const double area = projected_area_pixels(mesh, clip_from_object, scene.width, scene.height);
  Comparison cmp = compare_images(*frame.render, *frame.reference, thresholds, area);
  frame.max_error = cmp.interior.max_abs;
  frame.tolerance_share = cmp.interior_tolerance_share;
  frame.error = std::move(cmp.error);
  if (s.wireframe) {
    frame.verdict = "not judged";
    frame.detail = "wireframe: the reference draws filled triangles";
  } else if (s.gouraud) {
    frame.verdict = "not judged";
    frame.detail = "Gouraud: the reference's per-vertex Lambert, not the shader";
  } else {
    frame.verdict = cmp.pass ? "pass" : "fail";
    frame.detail = cmp.reason;
  }
  return finish(frame);
}

}  // namespace shaderbed::viewer
