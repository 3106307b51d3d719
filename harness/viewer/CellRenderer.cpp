#include "viewer/CellRenderer.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/Elapsed.h"
#include "lut/LookupTexture.h"
#include "lut/LutTolerance.h"
#include "run/CellDraw.h"
#include "run/LutDomain.h"
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

// What the case's reference may ask to draw: the original, as the frame's own cell is drawn.
class CellRenderer::Drawer final : public GroupDrawer {
 public:
  Drawer(CellRenderer& renderer, const CellGroup& group, const Mesh& mesh, const SceneSetup& scene)
      : renderer_(renderer), group_(group), mesh_(mesh), scene_(scene) {}
  const DrawAdditions* additions = nullptr;

  CellResult row(const PlannedCell& cell, const ReferenceSource& source) const override {
    return {.case_name = group_.c->name, .variant = group_.variant->name, .language = to_string(cell.language),
            .backend = cell.backend->name, .path = to_string(cell.path), .shape = group_.shape, .reference = source};
  }
  Result<Image> draw(const Variant& variant, const PlannedCell& cell, const TimingRequest&, CellResult&,
                     const Variation& variation) override {
    auto drawn = renderer_.draw_program(*group_.c, variant, cell.language, *cell.backend, cell.path, mesh_, scene_,
                                        false, additions, variation);
    if (!drawn) return std::unexpected(drawn.error());
    return std::move(drawn->image);
  }

 private:
  CellRenderer& renderer_;
  const CellGroup& group_;
  const Mesh& mesh_;
  const SceneSetup& scene_;
};

CellRenderer::CellRenderer(std::string probe_binary)
    : probe_(std::move(probe_binary)),
      programs_(std::make_unique<ProgramCache>(ProgramOptions{.opengl = true})),
      references_(std::make_unique<ReferenceKinds>(no_stored_)) {}

CellRenderer::~CellRenderer() = default;

BackendSlot& CellRenderer::backend(const std::string& name) {
  auto it = backends_.find(name);
  if (it == backends_.end())
    it = backends_.emplace(name, BackendSlot{name, name == "vulkan" ? make_vulkan_backend() : make_gl_backend()}).first;
  return it->second;
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

// Compiled by the probe first (viewer/CompileProbe.h), then drawn as `run` draws a cell.
Result<CellRenderer::Drawn> CellRenderer::draw_program(const Case& c, const Variant& variant, Language language,
                                                       BackendSlot& slot, ShaderPath path, const Mesh& mesh,
                                                       const SceneSetup& scene, bool wireframe,
                                                       const DrawAdditions* additions, const Variation& variation) {
  const std::string key = c.name + "/" + variant.name + "/" + to_string(language);
  if (!slot.backend) return std::unexpected(Error(slot.backend.error()).in_backend(slot.name));
  if (!probed_.contains(key)) {
    if (auto ok = probe_.compile(c, variant, language); !ok) return std::unexpected(ok.error());
    probed_.insert(key);
  }
  const CachedProgram& compiled = programs_->get(c, variant, language);
  if (!compiled.program) return std::unexpected(compiled.program.error());
  auto lut = lut_of(c, variant);
  if (!lut) return std::unexpected(lut.error());
  auto drawn = draw_cell(**slot.backend, {.c = c,
                                          .language = language,
                                          .path = path,
                                          .program = *compiled.program,
                                          .mesh = mesh,
                                          .scene = variation.scene ? *variation.scene : scene,
                                          .lut = *lut,
                                          .additions = additions,
                                          .bindings = variation.bindings,
                                          .flip_images = variation.flip_images,
                                          .fill = wireframe ? std::optional(FillMode::wireframe) : std::nullopt});
  if (!drawn) return std::unexpected(drawn.error());
  return Drawn{std::move(drawn->image), drawn->timings.draw_ms + drawn->timings.readback_ms};
}

Frame CellRenderer::draw(const FrameRequest& request) { return draw_frame(request, nullptr); }

Inspection CellRenderer::inspect(const InspectRequest& request) {
  const auto t0 = Clock::now();
  Inspection out{.state = request.frame.state, .x = request.x, .y = request.y};
  if (request.x < 0 || request.y < 0 || request.x >= request.frame.size || request.y >= request.frame.size) {
    out.note = fmt::format("pixel ({}, {}) is outside the {}x{} image", request.x, request.y, request.frame.size,
                           request.frame.size);
    return out;
  }
  const Frame frame = draw_frame(request.frame, &out);
  if (!out.explanation && out.note.empty()) out.note = frame.problem ? frame.problem->to_string() : "nothing was traced";
  out.ms = ms_since(t0);
  return out;
}

void CellRenderer::explain_pixel(GroupDrawer& drawer, const CellGroup& group, const CellReference& reference,
                                 const Frame& frame, Inspection& out) {
  if (!twins_) twins_ = std::make_unique<CellDivergence>();
  // The original's values are matched over a spread of pixels besides this one, as `run`
  // locates a divergence (a value is named by what it matches everywhere, not by chance).
  std::vector<twin::PixelAt> context;
  if (frame.render && frame.reference)
    context = divergence_pixels(*frame.render, *frame.reference, classify_pixels(*frame.reference));
  const PlannedCell& cell = group.cells.front();
  const CellResult row = drawer.row(cell, reference.source());
  auto explained = twins_->explain(drawer, group, cell, row, out.x, out.y, context);
  if (explained) out.explanation = std::move(*explained);
  else out.note = explained.error().message;
}

Frame CellRenderer::draw_frame(const FrameRequest& request, Inspection* inspection) {
  const auto t0 = Clock::now();
  Frame frame;
  frame.generation = request.generation;
  frame.state = request.state;
  const ViewerState& s = request.state;
  if (request.sources_changed) {
    programs_ = std::make_unique<ProgramCache>(ProgramOptions{.opengl = true});
    probed_.clear();
    luts_.clear();
    references_ = std::make_unique<ReferenceKinds>(no_stored_);
  }
  probe_.prepare();   // its start-up overlaps the backend's, on the first frame
  Case c = with_parameters(*request.c, s);
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
  if (auto ok = complete_case(c); !ok) return failed(ok.error());
  const Variant* variant = find_variant(c, s.variant_name());
  if (!variant) return failed(Error{.message = "no variant '" + s.variant_name() + "'", .file = c.path, .stage = ErrorStage::case_file});

  const std::string mesh_key = s.shape_name() + (c.tessellation == Tessellation::high ? "/high" : "/low");
  if (!meshes_.contains(mesh_key)) {
    auto mesh = make_shape(s.shape_name(), c.tessellation);
    if (!mesh) return failed(Error{.message = "unknown shape '" + s.shape_name() + "'", .stage = ErrorStage::options});
    meshes_.emplace(mesh_key, std::move(*mesh));
  }
  const Mesh& shape = meshes_.at(mesh_key);
  const SceneSetup scene = scene_of(s, request.size);
  const glm::dmat4 clip_from_object =
      projection_matrix(scene.camera, double(scene.width) / scene.height) * view_matrix(scene.camera) * scene.world;
  const double area = projected_area_pixels(shape, clip_from_object, scene.width, scene.height);

  // The frame's cell as a group of one, with the original's cell when the case has one.
  BackendSlot& slot = backend(s.backend);   // first, so it starts while the probe compiles
  CellGroup group{.c = &c, .variant = variant, .shape = s.shape_name(), .cells = {{s.language, &slot, s.path}}};
  if (c.reference_render) {
    const RenderReference& r = *c.reference_render;
    const Variant* original = r.variant.empty() ? variant : find_variant(c, r.variant);
    const auto path = parse_path(r.path);
    if (original && original->shaders.contains(r.language) && path) {
      group.reference_cell = PlannedCell{r.language, &backend(r.backend), *path};
      group.reference_variant = original;
    }
  }
  const CellSettings settings;
  const GroupScene group_scene{group, mesh_key, shape, scene, settings, area};
  // What the case's reference adds to its draws (an SH case's transfer streams and light).
  const Result<const DrawAdditions*> additions = references_->draw_inputs(group_scene);
  if (!additions) return failed(additions.error());
  const Mesh& mesh = *additions && (*additions)->mesh ? *(*additions)->mesh : shape;

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
    auto drawn = draw_program(c, *variant, s.language, slot, s.path, shape, scene, s.wireframe, *additions);
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

  // The reference, as `run` judges the cell (run/CellReference.h).
  Drawer drawer(*this, group, shape, scene);
  drawer.additions = *additions;
  const std::unique_ptr<CellReference> reference = references_->prepare(group_scene, drawer);
  if (const Result<ReferenceImage>* image = reference->group_image()) {
    if (*image) frame.reference = **image;
    else frame.reference_problem = image->error().to_string();
  } else {
    frame.reference_problem = "the case's reference is " + reference->source().label +
                              ": the viewer draws only model and original references";
  }
  if (inspection) explain_pixel(drawer, group, *reference, frame, *inspection);

  if (!frame.reference) {
    frame.verdict = "not judged";
    frame.detail = frame.reference_problem;
    return finish(frame);
  }
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
