#include "run/GroupRunner.h"

#include <algorithm>
#include <deque>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "backends/Backend.h"
#include "compare/Attribution.h"
#include "compare/ErrorMap.h"
#include "compare/ConventionFit.h"
#include "compare/ImageComparison.h"
#include "compare/ImageFiles.h"
#include "core/BoundedFile.h"
#include "core/Elapsed.h"
#include "core/Fnv1a.h"
#include "lut/LookupTexture.h"
#include "lut/LutTolerance.h"
#include "run/CellDraw.h"
#include "run/CellDivergence.h"
#include "run/CellTwins.h"
#include "run/LruCache.h"
#include "run/LutDomain.h"
#include "run/ProgramArtefacts.h"
#include "run/ProgramCache.h"
#include "run/ReferenceKinds.h"
#include "run/ReferenceRender.h"
#include "scene/CaseFile.h"
#include "scene/Primitives.h"
#include "scene/ProjectedArea.h"
#include "timing/MedianInterval.h"

namespace shaderbed {
namespace fs = std::filesystem;
namespace {

GpuTiming gpu_timing(const RenderTimings& t, const TimingRequest& request) {
  const auto interval = [](const std::vector<double>& ms) {
    const MedianInterval m = median_interval(ms);
    return TimingInterval{m.median, m.low, m.high, m.level};
  };
  return {t.gpu_clock, request.warmup, int(t.gpu_ms.size()), interval(t.gpu_ms), interval(t.wall_ms)};
}

// What the fits may use besides the two images; the images behind the counterfactuals
// live here (a deque keeps their addresses).
struct Evidence {
  std::optional<SurfaceSamples> surface;
  std::deque<ReferenceImage> images;
  std::vector<Counterfactual> counterfactuals;
  std::map<std::string, double> parameters;   // scalar case parameters, to name constants
};

struct Thresholds {
  double interior = 0, silhouette = 0, interior_rel = 0, silhouette_rel = 0, lut_bound = 0, texel_bound = 0;
  std::string lut_derivation, texel_derivation;
};

}  // namespace

struct GroupRunner::Impl final : GroupDrawer {
  std::optional<std::pair<std::string, std::optional<twin::PixelAt>>> explain_;   // request_explanation
  std::optional<Result<PixelExplanation>> explanation_;

  Impl(const CellSettings& settings, const SceneSetup& scene, const StoredReferences& stored, bool gl_programs,
       StepObserver on_step)
      : settings_(settings), scene_(scene), on_step_(std::move(on_step)), references_(stored),
        programs_({settings.relaxed_precision, settings.out_dir, gl_programs}), twins_(settings.twin) {}

  // Runs one case x variant x shape: every language, backend and path.
  std::vector<CellResult> run(const CellGroup& g) {
    const Case& c = *g.c;
    group_ = &g;
    group_label_ = c.name + "/" + g.variant->name + "/" + g.shape;
    // An isolated run gives every step a deadline and names the step a hung worker was in.
    announce(group_label_, "reference");
    twins_.begin_group();
    divergences_.begin_group();
    const std::string mesh_key = g.shape + (settings_.mesh_slices > 0 ? "/" + std::to_string(settings_.mesh_slices)
                                            : c.tessellation == Tessellation::high ? "/high" : "/low");
    if (!meshes_.contains(mesh_key))
      meshes_.emplace(mesh_key, *(settings_.mesh_slices > 0 ? make_shape(g.shape, settings_.mesh_slices)
                                                             : make_shape(g.shape, c.tessellation)));
    const Mesh& shape = meshes_.at(mesh_key);
    shape_ = &shape;
    if (!areas_.contains(mesh_key)) {
      const glm::dmat4 clip_from_object = projection_matrix(scene_.camera, double(scene_.width) / scene_.height) *
                                          view_matrix(scene_.camera) * scene_.world;
      areas_[mesh_key] = projected_area_pixels(shape, clip_from_object, scene_.width, scene_.height);
    }
    area_ = areas_.at(mesh_key);
    const fs::path dir = settings_.out_dir.empty() ? fs::path() : fs::path(settings_.out_dir) / c.name / g.variant->name / g.shape;

    thresholds_ = {c.interior.max_abs, c.silhouette.max_abs, c.interior.max_rel, c.silhouette.max_rel, 0, 0, "", ""};
    group_lut_ = prepare_lut(g, shape, thresholds_);
    const std::string scene_hash = scene_fingerprint(c, mesh_key);

    // The reference, prepared before any cell is drawn (the original's render may be one).
    const GroupScene group{g, mesh_key, shape, scene_, settings_, area_};
    const Result<const DrawAdditions*> additions = references_.draw_inputs(group);
    additions_ = additions ? *additions : nullptr;
    notes_textures_ = false;
    const auto t0 = Clock::now();
    const std::unique_ptr<CellReference> reference = references_.prepare(group, *this);
    const double reference_ms = ms_since(t0);
    notes_textures_ = reference->notes_textures();
    // A render reference that samples 8-bit textures widens every cell's bound by what one
    // filter rounding of them can move a pixel (on top of the fp32 one, as a LUT's bound).
    if (auto texels = reference->texel_bound(*this)) {
      thresholds_.interior += texels->interior;
      thresholds_.silhouette += texels->silhouette;
      thresholds_.texel_bound = texels->interior;
      thresholds_.texel_derivation = texels->derivation;
    }
    const Mesh& mesh = additions_ && additions_->mesh ? *additions_->mesh : shape;
    const ReferenceSource source = reference->source();
    const Result<ReferenceImage>* group_image = reference->group_image();
    group_reference_written_.reset();   // written with the first kept cell that is judged against it
    classes_ = group_image && *group_image ? classify_pixels(**group_image) : std::vector<PixelClass>{};

    std::vector<CellResult> results;
    std::vector<Image> images;   // kept for attribution, one per cell that rendered
    std::vector<size_t> rendered_cells;
    std::map<size_t, ReferenceImage> own_references;   // by results index: a failed cell's own reference
    for (size_t i = 0; i < g.cells.size(); ++i) {
      const PlannedCell& cell = g.cells[i];
      CellResult r = row(cell, source);
      Result<Image> image = fail(ErrorStage::draw, "not drawn");
      if (auto drawn = reference->take_drawn(i)) {   // drawn already, as the reference
        r = std::move(drawn->result);
        image = std::move(drawn->image);
        apply_thresholds(r);   // drawn before the texel bound was known
        r.reference.is_reference = true;
      } else if (!additions) {   // the reference's inputs failed: its error, not a binding error, in every cell
        image = std::unexpected(additions.error());
      } else {
        image = draw(*g.variant, cell, settings_.timing, r);
      }
      r.time_ms["reference"] = reference_ms;
      r.scene_hash = scene_hash;
      if (image) announce(r.id(), "write");
      Result<void> judged = image ? Result<void>{} : Result<void>(std::unexpected(image.error()));
      if (image) save_image(*image, r);
      if (judged && group_image) {
        judged = *group_image ? judge_cell(*image, **group_image, classes_, dir, false, r)
                              : Result<void>(std::unexpected(group_image->error()));
        if (judged) reference->judge(*image, r);
      } else if (judged) {
        Result<ReferenceImage> own = reference->cell_image(r);
        judged = own ? judge_cell(*image, *own, classify_pixels(*own), dir, true, r)
                     : Result<void>(std::unexpected(own.error()));
        if (judged && r.status == CellStatus::fail) own_references.emplace(results.size(), std::move(*own));
      }
      if (!judged) {
        r.status = judged.error().skipped ? CellStatus::skipped : CellStatus::error;
        r.message = judged.error().to_string();
        if (!judged.error().skipped) r.error_stage = to_string(judged.error().stage);
      } else {
        if (r.reference.is_reference)
          r.message = "the reference: every other cell of this case is judged against this render of the original";
        if (explain_ && r.id() == explain_->first) explain_pixel(g, cell, r, *image, group_image, reference.get());
        if (twins_.enabled()) {
          announce(r.id(), "twin");
          r.twin = twins_.figures(*this, *g.variant, cell, r, *image, group_image && *group_image ? &**group_image : nullptr);
          // A note on a passing cell too: desktop drivers hide what a 16-bit device shows.
          if (!r.twin->precision_note.empty()) r.warnings.push_back("precision: " + r.twin->precision_note);
        }
        images.push_back(std::move(*image));
        rendered_cells.push_back(results.size());
      }
      results.push_back(std::move(r));
    }
    announce(group_label_, "attribution");
    if (!group_image) {
      explain(*reference, g, mesh, results, images, rendered_cells, nullptr, own_references);
    } else if (*group_image) {
      attribute(g, results, images, rendered_cells, **group_image, thresholds_, source.label);
      explain(*reference, g, mesh, results, images, rendered_cells, &**group_image, own_references);
    }
    for (CellResult& r : results) attribute_by_twin(r);
    return results;
  }

  // A cell's row before it is drawn: its identity, thresholds and reference.
  CellResult row(const PlannedCell& cell, const ReferenceSource& source) const override {
    const CellGroup& g = *group_;
    CellResult r{.case_name = g.c->name, .variant = g.variant->name, .language = to_string(cell.language),
                 .backend = cell.backend->name, .path = to_string(cell.path), .shape = g.shape};
    r.tolerance_reason = g.c->interior.reason;
    apply_thresholds(r);
    r.reference = source;
    return r;
  }

  void apply_thresholds(CellResult& r) const {
    r.interior_threshold = thresholds_.interior;
    r.silhouette_threshold = thresholds_.silhouette;
    r.interior_threshold_rel = thresholds_.interior_rel;
    r.silhouette_threshold_rel = thresholds_.silhouette_rel;
    r.lut_bound = thresholds_.lut_bound;
    r.lut_derivation = thresholds_.lut_derivation;
    r.texel_bound = thresholds_.texel_bound;
    r.texel_derivation = thresholds_.texel_derivation;
  }

  // Compiles, binds and draws one cell of `variant`; fills r's compile and draw parts.
  Result<Image> draw(const Variant& variant, const PlannedCell& cell, const TimingRequest& timing, CellResult& r,
                     const Variation& variation = {}) override {
    const Case& c = *group_->c;
    // An isolated run times these steps and blames a crash on the step and cell named last.
    const auto step = [&](const char* what) { announce(r.id(), what); };
    step("compile");
    const CachedProgram& compiled = programs_.get(c, variant, cell.language);
    if (!compiled.program) return std::unexpected(compiled.program.error());
    r.time_ms["compile"] = compiled.ms;
    r.artefacts = compiled.sources;
    if (cell.path == ShaderPath::native_glsl && compiled.program->native_glsl_reduced_precision)
      reduced_precision_.insert(r.id());
    r.vertex_spirv_hash = spirv_hash(compiled.program->vertex.spirv);
    r.fragment_spirv_hash = spirv_hash(compiled.program->fragment.spirv);
    std::tie(r.vertex_instructions, r.fragment_instructions) = compiled.instructions;
    // The group's LUT (with its bound's errors), or another variant's own: an original in
    // another variant samples its LUT, not the port's.
    const Result<const Texture*> lut = &variant == group_->variant ? group_lut_ : variant_lut(c, variant);
    if (!lut) return std::unexpected(lut.error());
    if (!cell.backend->backend) return std::unexpected(Error(cell.backend->backend.error()).in_backend(cell.backend->name));

    const bool warn_unused = !variation.bindings && settings_.unused_binding_warnings;
    const CellDraw request{.c = c,
                           .language = cell.language,
                           .path = cell.path,
                           .program = *compiled.program,
                           .mesh = *shape_,
                           .scene = variation.scene ? *variation.scene : scene_,
                           .lut = *lut,
                           .additions = additions_,
                           .bindings = variation.bindings,
                           .flip_images = variation.flip_images,
                           .texel_step = variation.texel_step,
                           .timing = timing,
                           .other_sources = warn_unused ? &other_sources(c, variant, cell.language) : nullptr};
    step("draw");
    auto drawn = draw_cell(**cell.backend->backend, request);
    step("judge");
    if (!drawn) return std::unexpected(drawn.error());
    if (warn_unused) r.warnings = std::move(drawn->warnings);
    if (notes_textures_) r.reference_note = drawn->texture_note;
    const RenderTimings& t = drawn->timings;
    r.time_ms["build"] = t.build_ms;
    r.time_ms["draw"] = t.draw_ms;
    r.time_ms["readback"] = t.readback_ms;
    r.program_cached = t.program_cached;
    if (!t.gpu_ms.empty()) r.gpu = gpu_timing(t, timing);
    return std::move(drawn->image);
  }

 private:
  // Which named convention explains each failing cell (compare/ConventionFit.h). The fits
  // use the surface's N·L and |n|, and the reference drawn again under each convention a
  // port may get wrong (CellReference::counterfactuals); made once per group, and only
  // when a cell failed. `group_image` null: each cell's own reference (`own_references`).
  void explain(CellReference& reference, const CellGroup& g, const Mesh& mesh, std::vector<CellResult>& results,
               const std::vector<Image>& images, const std::vector<size_t>& rendered, const ReferenceImage* group_image,
               const std::map<size_t, ReferenceImage>& own_references) {
    if (std::ranges::none_of(rendered, [&](size_t i) { return results[i].status == CellStatus::fail; })) return;
    const Case& c = *g.c;
    Evidence evidence;
    if (auto surface = render_surface_samples(mesh, scene_, c)) evidence.surface = std::move(*surface);
    for (const auto& [name, values] : c.params)
      if (values.size() == 1) evidence.parameters[name] = values.front();
    for (Redrawn& redrawn : reference.counterfactuals(*this)) {
      if (!redrawn.image) continue;
      evidence.images.push_back(std::move(*redrawn.image));
      evidence.counterfactuals.push_back({redrawn.name, redrawn.detail, &evidence.images.back()});
    }
    for (size_t i = 0; i < rendered.size(); ++i) {
      CellResult& r = results[rendered[i]];
      if (r.status != CellStatus::fail) continue;
      if (group_image) {
        explain_cell(images[i], *group_image, classes_, evidence, r);
        // Where the shader departs from its original, or from the model's quantities.
        if (!r.reference.is_reference) {
          announce(r.id(), "divergence");
          const auto t0 = Clock::now();
          r.divergence = divergences_.locate(*this, g, g.cells[rendered[i]], r, images[i], *group_image, classes_, reference);
          if (r.divergence) r.time_ms["divergence"] = ms_since(t0);   // the first cell of a variant and language pays it
        }
      } else {
        const ReferenceImage& own = own_references.at(rendered[i]);
        explain_cell(images[i], own, classify_pixels(own), evidence, r);
      }
    }
  }

  static void explain_cell(const Image& image, const ReferenceImage& reference, const std::vector<PixelClass>& classes,
                           const Evidence& evidence, CellResult& r) {
    const ComparisonThresholds t{r.interior_threshold, r.silhouette_threshold, r.interior_threshold_rel,
                                 r.silhouette_threshold_rel};
    const ConventionEvidence fit_evidence{evidence.surface ? &*evidence.surface : nullptr, evidence.counterfactuals,
                                          evidence.parameters};
    for (const ConventionFit& fit : explain_difference(image, reference, classes, t, fit_evidence)) {
      // Only the best of a family (the four half-pixel directions), and only fits over pixels.
      const bool seen = std::ranges::any_of(r.explanations, [&](const Explanation& e) { return e.name == fit.name; });
      if (!seen && fit.pixels > 0)
        r.explanations.push_back({fit.name, fit.description, fit.residual, fit.rmse, fit.pixels, fit.fits, describe(fit)});
    }
    if (!r.explanations.empty()) return;
    // Coverage alone failed (a blank or misplaced render), which no colour fit explains: a
    // counterfactual that draws the same pixels does.
    for (const Counterfactual& cf : evidence.counterfactuals) {
      const bool both_blank = std::ranges::none_of(image.coverage, [](uint8_t v) { return v != 0; }) &&
                              std::ranges::none_of(cf.image->coverage, [](uint8_t v) { return v != 0; });
      if (both_blank || compare_images(image, *cf.image, t).pass)
        r.explanations.push_back({cf.name, "re-rendered with " + cf.detail, 0, 0, 0, true,
                                  "matches the reference re-rendered with " + cf.detail +
                                      (both_blank ? " (both draw nothing)" : " (coverage and colours)")});
    }
    if (r.explanations.empty() && r.attribution == "matrix convention")
      r.explanations.push_back({"matrix_convention", "coverage", 0, 0, 0, true,
                                "the coverage points at the row/column matrix convention: " + r.attribution_reason});
  }

  // Which stage the failures of this group point at, from how its renders agree.
  void attribute(const CellGroup& g, std::vector<CellResult>& results, const std::vector<Image>& images,
                 const std::vector<size_t>& rendered, const ReferenceImage& reference, const Thresholds& t,
                 const std::string& reference_label) {
    std::vector<RenderOutcome> outcomes;
    for (size_t i = 0; i < rendered.size(); ++i) {
      const CellResult& r = results[rendered[i]];
      outcomes.push_back({r.language, r.backend, r.path, r.status == CellStatus::pass, &images[i],
                          reduced_precision_.contains(r.id())});
    }
    const std::vector<Verdict> verdicts = attribute_failures(
        outcomes, reference, {t.interior, t.silhouette, t.interior_rel, t.silhouette_rel}, area_);
    // Against the original: renders of the port that all fail and agree with each other
    // point at the port's source, whichever languages and backends drew them.
    std::string port_reason;
    if (g.c->reference_render) {
      std::vector<const Image*> failing;
      std::set<std::string> failing_languages, passing_languages;
      for (size_t i = 0; i < rendered.size(); ++i) {
        const CellResult& r = results[rendered[i]];
        if (r.status == CellStatus::fail) failing.push_back(&images[i]), failing_languages.insert(r.language);
        else passing_languages.insert(r.language);
      }
      // A language that also passes somewhere is a backend's or path's fault, not its source's.
      const bool whole_languages = std::ranges::none_of(failing_languages, [&](const std::string& l) {
        return passing_languages.contains(l);
      });
      const double spread = renders_max_difference(failing, classes_);
      if (whole_languages && failing.size() > 1 && spread <= t.interior)
        port_reason = fmt::format("all {} failing renders agree with each other (max difference {:.3g}) and differ from "
                                  "the original, {}: the port's source computes something else",
                                  failing.size(), spread, reference_label);
    }
    // Never blame the port for what the original does itself: a failing port render that
    // agrees with the original's own render on the same backend (its same path first) shows
    // that backend's difference from the reference (GL's window y, a texel step), which a run
    // filtered to that backend cannot see from the other renders. port_reason is set only
    // for a case judged against its original's render.
    const std::string original = port_reason.empty() ? "" : to_string(g.c->reference_render->language);
    const auto original_agrees_on = [&](size_t i) -> std::string {
      const CellResult& r = results[rendered[i]];
      std::optional<size_t> same;
      for (size_t j = 0; j < rendered.size(); ++j) {
        const CellResult& o = results[rendered[j]];
        if (o.language == original && o.backend == r.backend && (!same || o.path == r.path)) same = j;
      }
      if (!same) return "";
      const Image* pair[] = {&images[i], &images[*same]};
      if (renders_max_difference(pair, classes_) > t.interior) return "";
      return results[rendered[*same]].backend + "/" + results[rendered[*same]].path;
    };
    for (size_t i = 0; i < rendered.size() && i < verdicts.size(); ++i) {
      CellResult& r = results[rendered[i]];
      const Verdict& v = verdicts[i];
      const bool geometry = v.attribution == Attribution::matrix_convention;
      const bool blameable = !port_reason.empty() && r.status == CellStatus::fail && !geometry && r.language != original;
      const std::string original_path = blameable ? original_agrees_on(i) : "";
      if (!original_path.empty()) {
        r.attribution = "driver";
        r.attribution_reason = fmt::format("the original drawn on {} differs from {} as this render does (they agree "
                                           "within the interior threshold), so not the port's source: {}",
                                           original_path, reference_label, v.reason);
      } else if (blameable) {
        r.attribution = "port";
        r.attribution_reason = port_reason;
      } else {
        r.attribution = to_string(v.attribution);
        r.attribution_reason = v.reason;
      }
    }
  }

  // `stem`.exr and `stem`.png.
  Result<void> write_reference(const ReferenceImage& ref, const fs::path& stem) {
    Image preview(ref.width, ref.height);
    for (size_t i = 0; i < ref.rgba.size(); ++i) preview.rgba[i] = float(ref.rgba[i]);
    preview.coverage = ref.coverage;
    if (auto ok = write_exr(stem.string() + ".exr", ref.width, ref.height, preview.rgba); !ok) return ok;
    return write_png(stem.string() + ".png", preview);
  }

  // The variant's LUT (nullptr when it has none), and the thresholds widened by the
  // LUT's derived error bound.
  Result<const Texture*> prepare_lut(const CellGroup& g, const Mesh& mesh, Thresholds& t) {
    const Case& c = *g.c;
    const Result<const Texture*> texture = variant_lut(c, *g.variant);
    if (!texture || !*texture) return texture;
    // Derived over the configurations this shape shows in the image, not the whole table.
    const Result<LutDomain> domain = c.lut->max_abs >= 0 ? Result<LutDomain>(LutDomain{}) : lut_domain(c, mesh, scene_, g.shape);
    if (!domain) return std::unexpected(Error(domain.error()).in_file(c.path));
    const Result<LutErrorBound> bound =
        c.lut->max_abs >= 0 ? Result<LutErrorBound>(LutErrorBound{c.lut->max_abs, c.lut->max_abs, "given in the case"})
                            : lut_error_bound(g.variant->lut, c.params, **texture, *domain);
    if (!bound) return std::unexpected(Error(bound.error()).in_file(c.path));
    // The LUT's own error comes on top of the fp32 one, in each region.
    t.interior += bound->max_abs;
    t.silhouette += bound->band_max_abs;
    t.lut_bound = bound->max_abs;
    t.lut_derivation = bound->derivation;
    return texture;
  }

  // The variant's generated LUT, made once per worker (nullptr when it has none).
  Result<const Texture*> variant_lut(const Case& c, const Variant& variant) {
    if (variant.lut.empty()) return nullptr;
    const std::string key = c.name + "/" + variant.name;
    const Result<Texture>* found = luts_.find(key);
    if (!found) {
      Result<Texture> made = generate_lut(variant.lut, c.params);
      size_t bytes = 1024;
      if (made) {
        bytes += made->texels.size() * sizeof(float);
        for (const std::vector<float>& level : made->mip_levels) bytes += level.size() * sizeof(float);
      }
      found = &luts_.put(key, std::move(made), bytes);
    }
    const Result<Texture>& texture = *found;
    if (!texture) return std::unexpected(Error(texture.error()).in_file(c.path));
    return &*texture;
  }

  // The texts of the case's other variants in `language`, read once per worker (every
  // cell of the variant asks), for the unused-binding check.
  const std::vector<std::string>& other_sources(const Case& c, const Variant& variant, Language language) {
    const std::string key = c.name + "/" + variant.name + "/" + to_string(language);
    if (const std::vector<std::string>* found = other_sources_.find(key)) return *found;
    std::vector<std::string> texts;
    size_t bytes = 0;
    for (const Variant& other : c.variants)
      if (&other != &variant && other.shaders.contains(language))
        for (const std::string* file : {&other.shaders.at(language).vertex, &other.shaders.at(language).fragment}) {
          texts.push_back(read_bounded_file(*file, "shader file", ErrorStage::compile).value_or(""));
          bytes += texts.back().size() + sizeof(std::string);
        }
    return other_sources_.put(key, std::move(texts), bytes);
  }

  // `--save-images DIR`: the render, whole, for later runs to be judged against.
  void save_image(const Image& image, CellResult& r) {
    if (settings_.save_images_dir.empty()) return;
    // Not saved (a full disk): the cell keeps its verdict and the set goes without it.
    if (auto ok = save_stored_image(settings_.save_images_dir, r, image); !ok) {
      r.warnings.push_back("stored image not saved: " + ok.error().to_string());
      return;
    }
    r.artefacts.stored_exr = (fs::path(settings_.save_images_dir) / stored_image_file(r)).string();
  }

  // What the image depends on besides the shaders: stored images drawn with another scene
  // are refused rather than compared.
  std::string scene_fingerprint(const Case& c, const std::string& mesh_key) const {
    std::string text = fmt::format("{}x{} {}", scene_.width, scene_.height, mesh_key);
    const auto add = [&text](const auto& v) {
      for (int i = 0; i < v.length(); ++i) text += fmt::format(" {:a}", double(v[i]));
    };
    add(scene_.camera.eye), add(scene_.camera.target), add(scene_.camera.up);
    add(scene_.lights.direction), add(scene_.lights.position), add(c.ambient.value_or(scene_.lights.ambient));
    for (int col = 0; col < 4; ++col) add(scene_.world[col]);
    text += fmt::format(" fov {:a} light {}", scene_.camera.fovy_degrees, int(c.light));
    for (const auto& [name, values] : c.params) {
      text += " " + name;
      for (double v : values) text += fmt::format(" {:a}", v);
    }
    return hex64(fnv1a64(text));
  }

  // Compares a drawn cell with its reference and writes its images under `dir`; a
  // reference of the cell's own is written beside the cell's render.
  Result<void> judge_cell(const Image& image, const ReferenceImage& reference, const std::vector<PixelClass>& classes,
                          const fs::path& dir, bool own_reference, CellResult& r) {
    announce(r.id(), "judge");
    const auto t0 = Clock::now();
    const Comparison cmp = compare_images(image, reference,
                                          {r.interior_threshold, r.silhouette_threshold, r.interior_threshold_rel,
                                           r.silhouette_threshold_rel},
                                          area_, &classes);
    r.time_ms["compare"] = ms_since(t0);
    r.metrics = cell_metrics(cmp);
    r.status = cmp.pass ? CellStatus::pass : CellStatus::fail;
    r.message = cmp.reason;

    // --keep-images: a green run writes no images unless asked (issue 29: a default run's
    // --out was 0.4 GB at 256 px, nearly all of it passing cells).
    const bool kept = settings_.keep_images == "all" || (settings_.keep_images == "failing" && !cmp.pass);
    if (dir.empty() || !kept) return {};
    announce(r.id(), "write");
    const std::string stem = fmt::format("{}-{}-{}", r.language, r.backend, r.path);
    r.artefacts.render_exr = (dir / (stem + ".exr")).string();
    r.artefacts.render_png = (dir / (stem + ".png")).string();
    r.artefacts.error_exr = (dir / (stem + ".error.exr")).string();
    r.artefacts.error_png = (dir / (stem + ".error.png")).string();
    r.artefacts.reference_png = (dir / "reference.png").string();
    const auto io_start = Clock::now();
    // An image that cannot be written (a full disk) costs the image, never the verdict:
    // the cell keeps its status and says what was lost.
    std::vector<std::string> lost;
    std::string why;
    const auto keep = [&](const Result<void>& written, std::string& path) {
      if (written) return;
      lost.push_back(fs::path(path).filename().string());
      why = written.error().message;
      path.clear();
    };
    if (own_reference) {
      r.artefacts.reference_png = (dir / (stem + ".reference.png")).string();
      keep(write_reference(reference, dir / (stem + ".reference")), r.artefacts.reference_png);
    } else {
      if (!group_reference_written_) group_reference_written_ = write_reference(reference, dir / "reference");
      keep(*group_reference_written_, r.artefacts.reference_png);
    }
    keep(write_exr(r.artefacts.render_exr, scene_.width, scene_.height, image.rgba), r.artefacts.render_exr);
    keep(write_png(r.artefacts.render_png, image), r.artefacts.render_png);
    keep(write_exr(r.artefacts.error_exr, scene_.width, scene_.height, cmp.error.rgba), r.artefacts.error_exr);
    // The error map in false colour from 0 to the cell's worst interior error (or its
    // threshold), the scale recorded for the reports' legend.
    const ErrorMap map = error_map(cmp.error, r.interior_threshold);
    r.artefacts.error_scale = map.scale;
    keep(write_error_map(r.artefacts.error_png, map), r.artefacts.error_png);
    if (r.artefacts.error_png.empty()) r.artefacts.error_scale = {};
    if (!lost.empty())
      r.warnings.push_back(fmt::format("{} image{} not written ({}; the verdict stands): {}", lost.size(),
                                       lost.size() == 1 ? "" : "s", why, fmt::join(lost, ", ")));
    r.time_ms["io"] = ms_since(io_start);
    return {};
  }

  void announce(const std::string& id, const char* step) const {
    if (on_step_) on_step_(id, step);
  }

  const CellSettings settings_;
  const SceneSetup& scene_;
  StepObserver on_step_;
  std::string group_label_;   // case/variant/shape: the steps of the group as a whole
  ReferenceKinds references_;
  ProgramCache programs_;
  std::map<std::string, Mesh> meshes_;              // shape/tessellation
  std::map<std::string, double> areas_;             // shape/tessellation: projected pixels
  // Bounded: a case of thousands of variants would otherwise keep a LUT per variant and,
  // per variant, the texts of all the others (quadratic in the variants).
  LruCache<Result<Texture>> luts_{64, size_t(256) << 20};   // case/variant
  LruCache<std::vector<std::string>> other_sources_{16, size_t(64) << 20};   // by case/variant/language
  std::optional<Result<void>> group_reference_written_;   // the group's reference.png, once written
  // The current group's.
  const CellGroup* group_ = nullptr;
  const Mesh* shape_ = nullptr;
  double area_ = 0;                                 // expected projected area, in pixels
  Thresholds thresholds_;
  Result<const Texture*> group_lut_ = nullptr;
  const DrawAdditions* additions_ = nullptr;        // what its reference adds to each draw
  bool notes_textures_ = false;
  std::set<std::string> reduced_precision_;   // cells whose path computes in reduced precision, by id
  std::vector<PixelClass> classes_;                 // its reference, classified once for all its cells
  CellTwins twins_;                                 // --twin
  CellDivergence divergences_;                      // where a failing port departs
  // explain_'s pixel of cell r (rendered as `image`), or where it is furthest from its
  // reference, traced against the context of divergence_pixels.
  void explain_pixel(const CellGroup& g, const PlannedCell& cell, const CellResult& r, const Image& image,
                     const Result<ReferenceImage>* group_image, const CellReference* reference) {
    announce(r.id(), "divergence");
    std::vector<twin::PixelAt> context;
    std::optional<ReferenceImage> own;
    const ReferenceImage* against = group_image && *group_image ? &**group_image : nullptr;
    if (!against && reference)
      if (auto image_of = reference->cell_image(r)) own = std::move(*image_of), against = &*own;
    if (against) context = divergence_pixels(image, *against, own ? classify_pixels(*own) : classes_);
    std::optional<twin::PixelAt> pixel = explain_->second;
    if (!pixel && !context.empty()) pixel = context.front();
    if (!pixel) {
      explanation_ = fail(ErrorStage::twin, "no pixel of the shape to explain: name one with --pixel X,Y");
      return;
    }
    // The model's quantities in the order explain() traces: this pixel first.
    std::erase_if(context, [&](const twin::PixelAt& p) { return p.x == pixel->x && p.y == pixel->y; });
    context.insert(context.begin(), *pixel);
    const std::vector<twin::Counterpart> model = reference ? reference->quantities(context) : std::vector<twin::Counterpart>{};
    explanation_ = divergences_.explain(*this, g, cell, r, pixel->x, pixel->y, context, model);
  }
};

GroupRunner::GroupRunner(const CellSettings& settings, const SceneSetup& scene, const StoredReferences& stored,
                         bool gl_programs, StepObserver on_step)
    : impl_(std::make_unique<Impl>(settings, scene, stored, gl_programs, std::move(on_step))) {}
GroupRunner::~GroupRunner() = default;

void GroupRunner::request_explanation(std::string cell_id, std::optional<twin::PixelAt> pixel) {
  impl_->explain_ = std::pair{std::move(cell_id), pixel};
  impl_->explanation_.reset();
}

std::optional<Result<PixelExplanation>> GroupRunner::take_explanation() { return std::exchange(impl_->explanation_, std::nullopt); }

std::vector<CellResult> GroupRunner::run(const CellGroup& g) { return impl_->run(g); }

}  // namespace shaderbed
