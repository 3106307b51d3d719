#include "run/GroupRunner.h"


#include <algorithm>
#include <chrono>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "backends/Backend.h"
#include "core/Elapsed.h"
#include "run/CaseTextures.h"
#include "run/CaseUniforms.h"
#include "run/CellPlan.h"
#include "run/LutScale.h"
#include "run/ProgramArtefacts.h"
#include "run/ProgramCache.h"
#include "run/ReferenceRender.h"
#include "run/StoredImages.h"
#include "core/BoundedFile.h"
#include "core/CacheSettings.h"
#include "prt/ShCase.h"
#include "core/Fnv1a.h"
#include "reference/Reference.h"
#include "compare/Attribution.h"
#include "compare/ConventionFit.h"
#include "compare/ImageComparison.h"
#include "compare/ImageFiles.h"
#include "compile/Compiler.h"
#include "lut/LookupTexture.h"
#include "reference/ModelRegistry.h"
#include "lut/LutTolerance.h"
#include "scene/CaseFile.h"
#include "scene/NameFilter.h"
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

// A re-draw of the original under a convention a port may get wrong (a counterfactual).
struct Variation {
  const SceneSetup* scene = nullptr;        // null: the run's
  const BindingTable* bindings = nullptr;   // null: the case's for the cell's language
  bool flip_images = false;                 // every 2D image file upside down
};

// Everything computed once and shared by the cells that need it.
struct Caches {
  explicit Caches(const RunOptions& o) : programs({o.relaxed_precision, o.out_dir, wanted(o.backends, "gl")}) {}
  ProgramCache programs;
  std::map<std::string, Mesh> meshes;                        // shape/tessellation
  std::map<std::string, double> areas;                       // shape/tessellation: projected pixels
  std::map<std::string, Result<Texture>> luts;               // case/variant
  std::map<std::string, Result<ShPrepared>> sh;              // SH case/shape/tessellation
};

class GroupWork {
 public:
  GroupWork(const RunOptions& o, const SceneSetup& scene, const StoredReferences& stored)
      : o_(o), scene_(scene), stored_(stored), caches_(o) {}

  // Runs one case x variant x shape: every language, backend and path.
  std::vector<CellResult> run(const CellGroup& g) {
    const Case& c = *g.c;
    const std::string mesh_key = g.shape + (o_.mesh_slices > 0 ? "/" + std::to_string(o_.mesh_slices)
                                            : c.tessellation == Tessellation::high ? "/high" : "/low");
    if (!caches_.meshes.contains(mesh_key))
      caches_.meshes.emplace(mesh_key, *(o_.mesh_slices > 0 ? make_shape(g.shape, o_.mesh_slices)
                                                              : make_shape(g.shape, c.tessellation)));
    // An SH case draws the shape with its per-vertex transfer streams (harness/prt).
    const ShPrepared* prepared = nullptr;
    Result<void> sh_ready{};
    if (is_sh_model(c.model)) {
      const std::string key = c.name + "|" + mesh_key;
      if (!caches_.sh.contains(key)) {
        const std::string root = cache_settings().root;
        caches_.sh.emplace(key, prepare_sh(c, caches_.meshes.at(mesh_key), scene_,
                                           root.empty() ? fs::path() : fs::path(root) / "sh"));
      }
      const Result<ShPrepared>& entry = caches_.sh.at(key);
      if (entry) prepared = &*entry;
      else sh_ready = std::unexpected(entry.error());
    }
    sh_values_ = prepared ? &prepared->uniforms : nullptr;
    sh_textures_ = prepared ? &prepared->textures : nullptr;
    const Mesh& mesh = prepared ? prepared->mesh : caches_.meshes.at(mesh_key);
    const fs::path dir = o_.out_dir.empty() ? fs::path() : fs::path(o_.out_dir) / c.name / g.variant->name / g.shape;

    if (!caches_.areas.contains(mesh_key)) {
      const glm::dmat4 clip_from_object = projection_matrix(scene_.camera, double(scene_.width) / scene_.height) *
                                          view_matrix(scene_.camera) * scene_.world;
      caches_.areas[mesh_key] = projected_area_pixels(mesh, clip_from_object, scene_.width, scene_.height);
    }
    area_ = caches_.areas.at(mesh_key);

    Thresholds thresholds{c.interior.max_abs, c.silhouette.max_abs, c.interior.max_rel, c.silhouette.max_rel, 0, ""};
    Result<const Texture*> lut = prepare_lut(g, mesh, thresholds);
    const std::string scene_hash = scene_fingerprint(c, mesh_key);
    // --against DIR, or the case's `reference = { images = "DIR" }`: each cell its own image.
    const std::string& stored_dir = o_.against_dir.empty() ? c.reference_images : o_.against_dir;
    const StoredRun* stored = stored_dir.empty() ? nullptr : &stored_.runs.at(stored_dir);
    stored_evidence_.reset();

    // The reference: the model in double, or the original's render (drawn first; when it is
    // one of the group's cells, that cell's own draw is the reference).
    std::optional<size_t> reference_index;
    std::optional<Drawn> reference_draw;
    ReferenceSource source;
    const auto t0 = Clock::now();
    Result<ReferenceImage> reference = fail("reference", "not drawn");
    if (stored) {
      source = {"images", "images in " + stored->dir, false, stored_.toolchain_notes.at(stored_dir)};
    } else if (is_sh_model(c.model)) {
      // Its own mode even for a per-pixel reference (sweep): a per-vertex SH technique has
      // no per-pixel truncated SH, and its error against the exact integral is what a
      // sweep charts.
      const LightingMode mode = g.variant->mode;
      if (prepared) reference = render_reference(mesh, scene_, c, mode, *prepared->truncated);
      else reference = std::unexpected(sh_ready.error());
      source = {"model", c.model + ": the truncated SH in double" +
                             (mode == LightingMode::per_pixel ? std::string(" (per pixel)") : " (per vertex)")};
      if (prepared && prepared->exact) {
        auto exact = render_reference(mesh, scene_, c, mode, *prepared->exact);
        sh_exact_ = exact ? std::optional<ReferenceImage>(std::move(*exact)) : std::nullopt;
      } else {
        sh_exact_.reset();
      }
    } else if (!c.differential()) {
      const LightingMode mode = o_.per_pixel_reference ? LightingMode::per_pixel : g.variant->mode;
      reference = render_reference(mesh, scene_, c, mode);
      source = {"model", c.model + (mode == LightingMode::per_pixel ? " (per pixel)" : " (per vertex)")};
    } else {
      source = {"render", original_label(g)};
      reference_index = original_among_cells(g);
      reference = draw_original(g, mesh, lut, thresholds, source, reference_index, reference_draw);
    }
    const double reference_ms = ms_since(t0);
    if (reference && !dir.empty()) (void)write_reference(*reference, dir / "reference");
    classes_ = reference ? classify_pixels(*reference) : std::vector<PixelClass>{};

    std::vector<CellResult> results;
    std::vector<Image> images;   // kept for attribution, one per cell that rendered
    std::vector<size_t> rendered_cells;
    for (size_t i = 0; i < g.cells.size(); ++i) {
      const PlannedCell& cell = g.cells[i];
      CellResult r = row(g, cell, thresholds, source);
      Result<Image> image = fail("draw", "not drawn");
      if (reference_index == i && reference_draw) {   // drawn already, as the reference
        r = std::move(reference_draw->result);
        image = std::move(reference_draw->image);
        r.reference.is_reference = true;
      } else if (!sh_ready) {   // the SH precompute failed: its error, not a binding error, in every cell
        image = std::unexpected(sh_ready.error());
      } else {
        image = draw_cell(c, *g.variant, cell, mesh, lut, o_.timing, r);
      }
      r.time_ms["reference"] = reference_ms;
      r.scene_hash = scene_hash;
      Result<void> judged = !image ? Result<void>(std::unexpected(image.error())) : save_image(*image, r);
      if (judged && stored) {
        const Result<ReferenceImage> own = load_stored_image(*stored, r.id(), scene_hash);
        judged = own ? judge_cell(*image, *own, classify_pixels(*own), dir, r)
                     : Result<void>(std::unexpected(own.error()));
        if (judged && r.status == "fail") explain_cell(*image, *own, classify_pixels(*own), stored_evidence(c, mesh), r);
      } else if (judged) {
        judged = reference ? judge_cell(*image, *reference, classes_, dir, r)
                           : Result<void>(std::unexpected(reference.error()));
        if (judged && prepared) judge_sh(c, *prepared, *image, *reference, r);
      }
      if (!judged) {
        r.status = judged.error().skipped ? "skipped" : "error";
        r.message = judged.error().to_string();
      } else {
        if (r.reference.is_reference)
          r.message = "the reference: every other cell of this case is judged against this render of the original";
        images.push_back(std::move(*image));
        rendered_cells.push_back(results.size());
      }
      results.push_back(std::move(r));
    }
    if (reference && !stored) {
      attribute(g, results, images, rendered_cells, *reference, thresholds);
      explain(g, mesh, lut, results, images, rendered_cells, *reference);
    }
    return results;
  }

 private:
  struct Thresholds {
    double interior, silhouette, interior_rel, silhouette_rel, lut_bound;
    std::string lut_derivation;
  };

  struct Drawn {
    CellResult result;
    Image image;
  };

  // Which named convention explains each failing cell (compare/ConventionFit.h). The fits
  // use the surface's N·L and |n|, and the reference drawn again under each convention a
  // port may get wrong (the model re-rendered, or the original re-drawn with the light
  // negated, its matrices transposed, its images upside down); made once per group, and
  // only when a cell failed.
  void explain(const CellGroup& g, const Mesh& mesh, const Result<const Texture*>& lut, std::vector<CellResult>& results,
               const std::vector<Image>& images, const std::vector<size_t>& rendered, const ReferenceImage& reference) {
    if (std::ranges::none_of(rendered, [&](size_t i) { return results[i].status == "fail"; })) return;
    const Case& c = *g.c;
    Evidence evidence = surface_evidence(c, mesh);
    const auto add = [&](Result<ReferenceImage> image, const char* name, const char* detail) {
      if (!image) return;
      evidence.images.push_back(std::move(*image));
      evidence.counterfactuals.push_back({name, detail, &evidence.images.back()});
    };
    if (!c.differential()) {
      const LightingMode mode = o_.per_pixel_reference ? LightingMode::per_pixel : g.variant->mode;
      add(render_reference(mesh, scene_, c, mode, {.negate_light = true}), "negated_light",
          "the light vector negated (L → −L)");
      add(render_reference(mesh, scene_, c, mode, {.negate_eye = true}), "negated_eye", "the eye vector negated (V → −V)");
      if (mode == LightingMode::per_pixel)
        add(render_reference(mesh, scene_, c, mode, {.unnormalised_normal = true}), "unnormalised_normal_model",
            "the interpolated normal not renormalised");
    } else if (g.reference_cell) {
      const auto redraw = [&](const Variation& variation) -> Result<ReferenceImage> {
        CellResult scratch = row(g, *g.reference_cell, {}, {});
        auto image = draw_cell(c, *g.reference_variant, *g.reference_cell, mesh, lut, {.warmup = 0, .runs = 1}, scratch,
                               variation);
        if (!image) return std::unexpected(image.error());
        return as_reference(*image);
      };
      SceneSetup negated = scene_;
      negated.lights.direction = -negated.lights.direction;
      add(redraw({.scene = &negated}), "negated_light", "the light vector negated (L → −L)");
      if (const auto transposed = transposed_matrices(c, g.reference_cell->language))
        add(redraw({.bindings = &*transposed}), "transposed_matrices",
            "its matrices in the other row/column convention (transposed)");
      add(redraw({.flip_images = true}), "flipped_texture_v", "its textures upside down (v → 1 − v)");
      // D3D9 put pixel centres on integers: a port that keeps (or adds) that offset draws
      // everything half a pixel off, in one of four directions.
      static const char* const kShifts[] = {"the geometry half a pixel right and up (D3D9 pixel centres)",
                                            "the geometry half a pixel left and up (D3D9 pixel centres)",
                                            "the geometry half a pixel right and down (D3D9 pixel centres)",
                                            "the geometry half a pixel left and down (D3D9 pixel centres)"};
      for (int k = 0; k < 4; ++k) {
        SceneSetup shifted = scene_;
        shifted.clip_offset = {(k % 2 ? -1.0 : 1.0) / scene_.width, (k / 2 ? -1.0 : 1.0) / scene_.height};
        add(redraw({.scene = &shifted}), "half_pixel_offset_redrawn", kShifts[k]);
      }
    }
    for (size_t i = 0; i < rendered.size(); ++i)
      if (results[rendered[i]].status == "fail") explain_cell(images[i], reference, classes_, evidence, results[rendered[i]]);
  }

  // What the fits may use besides the two images; the images behind the counterfactuals
  // live here (a deque keeps their addresses).
  struct Evidence {
    std::optional<SurfaceSamples> surface;
    std::deque<ReferenceImage> images;
    std::vector<Counterfactual> counterfactuals;
    std::map<std::string, double> parameters;   // scalar case parameters, to name constants
  };

  Evidence surface_evidence(const Case& c, const Mesh& mesh) const {
    Evidence evidence;
    if (auto surface = render_surface_samples(mesh, scene_, c)) evidence.surface = std::move(*surface);
    for (const auto& [name, values] : c.params)
      if (values.size() == 1) evidence.parameters[name] = values.front();
    return evidence;
  }

  // A stored image has no counterfactuals: the surface and the image-space fits only.
  const Evidence& stored_evidence(const Case& c, const Mesh& mesh) {
    if (!stored_evidence_) stored_evidence_ = surface_evidence(c, mesh);
    return *stored_evidence_;
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

  static ReferenceImage as_reference(const Image& image) {
    return {image.width, image.height, std::vector<double>(image.rgba.begin(), image.rgba.end()), image.coverage};
  }

  // The case's bindings for `language` with every matrix in the other row/column
  // convention, or nothing when it binds no matrix.
  std::optional<BindingTable> transposed_matrices(const Case& c, Language language) const {
    const auto table = c.bindings.find(language);
    if (table == c.bindings.end()) return std::nullopt;
    const NamedValues values = bindable_values(scene_, c);
    BindingTable flipped = table->second;
    bool any = false;
    for (auto& [name, binding] : flipped) {
      const auto value = values.find(binding.single_name());
      if (value == values.end() || (value->second.size() != 16 && value->second.size() != 9)) continue;
      binding.layout = binding.layout == MatrixLayout::row_vector ? MatrixLayout::column_vector : MatrixLayout::row_vector;
      any = true;
    }
    if (!any) return std::nullopt;
    return flipped;
  }

  // A cell's row before it is drawn: its identity, thresholds and reference.
  static CellResult row(const CellGroup& g, const PlannedCell& cell, const Thresholds& t, const ReferenceSource& source) {
    CellResult r{.case_name = g.c->name, .variant = g.variant->name, .language = to_string(cell.language),
                 .backend = cell.backend->name, .path = to_string(cell.path), .shape = g.shape};
    r.interior_threshold = t.interior;
    r.silhouette_threshold = t.silhouette;
    r.interior_threshold_rel = t.interior_rel;
    r.silhouette_threshold_rel = t.silhouette_rel;
    r.tolerance_reason = g.c->interior.reason;
    r.lut_bound = t.lut_bound;
    r.lut_derivation = t.lut_derivation;
    r.reference = source;
    return r;
  }

  // "hlsl vulkan/spirv" (and the variant when it is another one).
  static std::string original_label(const CellGroup& g) {
    const RenderReference& r = *g.c->reference_render;
    std::string label = fmt::format("{} {}/{}", to_string(r.language), r.backend, r.path);
    if (!r.variant.empty()) label += " (variant " + r.variant + ")";
    return label;
  }

  // Which of the group's cells draws the original, if the filters kept it.
  static std::optional<size_t> original_among_cells(const CellGroup& g) {
    if (!g.reference_cell || g.reference_variant != g.variant) return std::nullopt;
    for (size_t i = 0; i < g.cells.size(); ++i) {
      const PlannedCell& cell = g.cells[i];
      if (cell.language == g.reference_cell->language && cell.backend == g.reference_cell->backend &&
          cell.path == g.reference_cell->path)
        return i;
    }
    return std::nullopt;
  }

  // Draws the differential case's original and turns it into the reference: double RGBA and
  // its coverage. The original must itself look like the shape (coverage near the mesh's
  // projected area); a blank or misplaced original judges nothing.
  Result<ReferenceImage> draw_original(const CellGroup& g, const Mesh& mesh, const Result<const Texture*>& lut,
                                       const Thresholds& t, const ReferenceSource& source, std::optional<size_t> index,
                                       std::optional<Drawn>& drawn) {
    const Case& c = *g.c;
    const std::string label = original_label(g);
    if (!g.reference_cell)
      return std::unexpected(Error{.message = "the reference backend '" + c.reference_render->backend +
                                              "' has no path '" + c.reference_render->path + "'",
                                   .file = c.path, .line = c.reference_render->line, .stage = "reference"});
    CellResult r = row(g, *g.reference_cell, t, source);
    // As a cell of the run it is timed like the others; drawn only as the reference, once.
    const TimingRequest timing = index ? o_.timing : TimingRequest{.warmup = 0, .runs = 1};
    Result<Image> image = draw_cell(c, *g.reference_variant, *g.reference_cell, mesh, lut, timing, r);
    if (!image)
      return std::unexpected(Error{.message = "the original (" + label + ") could not be drawn: " + image.error().to_string(),
                                   .file = c.path, .line = c.reference_render->line, .stage = "reference"});
    ReferenceImage reference = as_reference(*image);
    const Comparison itself = compare_images(*image, reference, {}, area_);
    if (itself.degenerate || itself.blank || itself.interior.pixels == 0)
      return std::unexpected(Error{.message = "the original (" + label + ") is no reference: " + itself.reason,
                                   .file = c.path, .line = c.reference_render->line, .stage = "reference"});
    if (index) drawn = Drawn{std::move(r), std::move(*image)};
    return reference;
  }

  // Which stage the failures of this group point at, from how its renders agree.
  void attribute(const CellGroup& g, std::vector<CellResult>& results, const std::vector<Image>& images,
                 const std::vector<size_t>& rendered, const ReferenceImage& reference, const Thresholds& t) {
    std::vector<RenderOutcome> outcomes;
    for (size_t i = 0; i < rendered.size(); ++i) {
      const CellResult& r = results[rendered[i]];
      outcomes.push_back({r.language, r.backend, r.path, r.status == "pass", &images[i]});
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
        if (r.status == "fail") failing.push_back(&images[i]), failing_languages.insert(r.language);
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
                                  failing.size(), spread, results.front().reference.label);
    }
    for (size_t i = 0; i < rendered.size() && i < verdicts.size(); ++i) {
      CellResult& r = results[rendered[i]];
      const Verdict& v = verdicts[i];
      const bool geometry = v.attribution == Attribution::matrix_convention;
      if (!port_reason.empty() && r.status == "fail" && !geometry) {
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
    if (g.variant->lut.empty()) return nullptr;
    const std::string key = c.name + "/" + g.variant->name;
    if (!caches_.luts.contains(key)) caches_.luts.emplace(key, generate_lut(g.variant->lut, c.params));
    const Result<Texture>& texture = caches_.luts.at(key);
    if (!texture) return std::unexpected(Error(texture.error()).in_file(c.path));
    // Derived over the configurations this shape shows in the image, not the whole table.
    const Result<LutDomain> domain = c.lut->max_abs >= 0 ? Result<LutDomain>(LutDomain{}) : lut_domain(c, mesh, scene_, g.shape);
    if (!domain) return std::unexpected(Error(domain.error()).in_file(c.path));
    const Result<LutErrorBound> bound =
        c.lut->max_abs >= 0 ? Result<LutErrorBound>(LutErrorBound{c.lut->max_abs, c.lut->max_abs, "given in the case"})
                            : lut_error_bound(g.variant->lut, c.params, *texture, *domain);
    if (!bound) return std::unexpected(Error(bound.error()).in_file(c.path));
    // The LUT's own error comes on top of the fp32 one, in each region.
    t.interior += bound->max_abs;
    t.silhouette += bound->band_max_abs;
    t.lut_bound = bound->max_abs;
    t.lut_derivation = bound->derivation;
    return &*texture;
  }

  // The texts of the case's other variants in `language`, read once per worker (every
  // cell of the variant asks), for the unused-binding check.
  const std::vector<std::string>& other_sources(const Case& c, const Variant& variant, Language language) {
    const std::string key = c.name + "/" + variant.name + "/" + to_string(language);
    auto [it, added] = other_sources_.try_emplace(key);
    if (added)
      for (const Variant& other : c.variants)
        if (&other != &variant && other.shaders.contains(language))
          for (const std::string* file : {&other.shaders.at(language).vertex, &other.shaders.at(language).fragment})
            it->second.push_back(read_bounded_file(*file, "shader file", "compile").value_or(""));
    return it->second;
  }

  // Compiles, binds and draws one cell of `variant`; fills r's compile and draw parts.
  Result<Image> draw_cell(const Case& c, const Variant& variant, const PlannedCell& cell, const Mesh& mesh,
                          const Result<const Texture*>& lut, const TimingRequest& timing, CellResult& r,
                          const Variation& variation = {}) {
    const SceneSetup& scene = variation.scene ? *variation.scene : scene_;
    // An isolated run times these steps and blames a crash on the step and cell named last.
    const auto step = [&](const char* what) {
      if (o_.on_step) o_.on_step(r.id(), what);
    };
    step("compile");
    const CachedProgram& compiled = caches_.programs.get(c, variant, cell.language);
    if (!compiled.program) return std::unexpected(compiled.program.error());
    r.time_ms["compile"] = compiled.ms;
    r.artefacts = compiled.sources;
    r.vertex_spirv_hash = spirv_hash(compiled.program->vertex.spirv);
    r.fragment_spirv_hash = spirv_hash(compiled.program->fragment.spirv);
    std::tie(r.vertex_instructions, r.fragment_instructions) = compiled.instructions;
    if (!lut) return std::unexpected(lut.error());
    if (!cell.backend->backend) return std::unexpected(Error(cell.backend->backend.error()).in_backend(cell.backend->name));

    auto bindings = c.bindings.find(cell.language);
    static const BindingTable no_bindings;
    const BindingTable& table = variation.bindings              ? *variation.bindings
                                : bindings == c.bindings.end() ? no_bindings
                                                               : bindings->second;
    NamedValues values = bindable_values(scene, c);
    if (sh_values_) values.insert(sh_values_->begin(), sh_values_->end());
    CaseUniforms uniforms(table, std::move(values), c.path);
    if (auto bound = uniforms.check_all_bound(*compiled.program); !bound) return std::unexpected(bound.error());
    // The table serves every variant in this language: only a run of them all can tell a
    // binding none of them declares (a --variant filter would compile the others just for it).
    if (!variation.bindings && o_.variants.empty())
      r.warnings = uniforms.unused_bindings(*compiled.program, other_sources(c, variant, cell.language));
    CaseTextures textures(table, c.textures.for_language(cell.language), *lut, c.path,
                          &compiled.program->sampler_settings, sh_textures_);
    if (auto ok = textures.check(*compiled.program); !ok) return std::unexpected(ok.error());
    if (variation.flip_images && !textures.flip_images_vertically()) return fail("counterfactual", "no image to flip");
    // A model reads no texture; a render of the original reads the same ones.
    if (!c.differential()) r.reference_note = textures.reference_note();
    DrawJob job{*compiled.program, cell.path, mesh, uniforms, scene.width, scene.height, &textures, timing};
    job.render_state = compiled.program->render_state;  // a DX9 effect pass's states
    const auto attributes = c.attributes.find(cell.language);
    if (attributes != c.attributes.end()) job.attributes = &attributes->second;
    step("draw");
    auto rendered = (*cell.backend->backend)->render(job);
    step("judge");
    if (!rendered)
      return std::unexpected(Error(rendered.error()).in_backend(cell.backend->name + "/" + to_string(cell.path)));
    const RenderTimings& t = rendered->timings;
    r.time_ms["build"] = t.build_ms;
    r.time_ms["draw"] = t.draw_ms;
    r.time_ms["readback"] = t.readback_ms;
    r.program_cached = t.program_cached;
    if (!t.gpu_ms.empty()) r.gpu = gpu_timing(t, timing);
    return std::move(rendered->image);
  }

  // Compares a drawn cell with its reference and writes its images under `dir`.
  // `--save-images DIR`: the render, whole, for later runs to be judged against.
  Result<void> save_image(const Image& image, CellResult& r) {
    if (o_.save_images_dir.empty()) return {};
    if (auto ok = save_stored_image(o_.save_images_dir, r, image); !ok) return ok;
    r.artefacts.stored_exr = (fs::path(o_.save_images_dir) / stored_image_file(r)).string();
    return {};
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

  Result<void> judge_cell(const Image& image, const ReferenceImage& reference, const std::vector<PixelClass>& classes,
                          const fs::path& dir, CellResult& r) {
    const auto t0 = Clock::now();
    const Comparison cmp = compare_images(image, reference,
                                          {r.interior_threshold, r.silhouette_threshold, r.interior_threshold_rel,
                                           r.silhouette_threshold_rel},
                                          area_, &classes);
    r.time_ms["compare"] = ms_since(t0);
    r.metrics = cell_metrics(cmp);
    r.status = cmp.pass ? "pass" : "fail";
    r.message = cmp.reason;

    if (dir.empty()) return {};
    const std::string stem = fmt::format("{}-{}-{}", r.language, r.backend, r.path);
    r.artefacts.render_exr = (dir / (stem + ".exr")).string();
    r.artefacts.render_png = (dir / (stem + ".png")).string();
    r.artefacts.error_exr = (dir / (stem + ".error.exr")).string();
    r.artefacts.error_png = (dir / (stem + ".error.png")).string();
    r.artefacts.reference_png = (dir / "reference.png").string();
    const auto io_start = Clock::now();
    // A stored image is each cell's own reference: written beside the cell's render.
    if (r.reference.kind == "images") {
      r.artefacts.reference_png = (dir / (stem + ".reference.png")).string();
      if (auto ok = write_reference(reference, dir / (stem + ".reference")); !ok) return ok;
    }
    for (auto written : {write_exr(r.artefacts.render_exr, scene_.width, scene_.height, image.rgba),
                         write_png(r.artefacts.render_png, image),
                         write_exr(r.artefacts.error_exr, scene_.width, scene_.height, cmp.error.rgba),
                         // Error heat map: the interior tolerance shows as mid grey.
                         write_png(r.artefacts.error_png, cmp.error, float(0.5 / std::max(r.interior_threshold, 1e-12)))})
      if (!written) return written;
    r.time_ms["io"] = ms_since(io_start);
    return {};
  }

  // An SH cell against the exact integral: the render's error and the approximation's own
  // (truncated SH in double against exact), over the pixels both cover; a case's
  // `[tolerance] approximation` bounds the latter.
  void judge_sh(const Case& c, const ShPrepared& prepared, const Image& image, const ReferenceImage& truncated,
                CellResult& r) const {
    CellResult::ShErrors e;
    e.summary = prepared.summary;
    e.precompute_ms = prepared.precompute_ms;
    e.bytes_per_vertex = double(prepared.bytes_per_vertex);
    if (sh_exact_) {
      double render_error = 0, truncation = 0, squares = 0;
      size_t count = 0;
      for (size_t p = 0; p < sh_exact_->coverage.size(); ++p) {
        if (!sh_exact_->coverage[p] || !truncated.coverage[p] || !image.coverage[p]) continue;
        for (int k = 0; k < 3; ++k) {
          const double exact = sh_exact_->rgba[p * 4 + k];
          const double d = std::abs(double(image.rgba[p * 4 + k]) - exact);
          render_error = std::max(render_error, d);
          squares += d * d;
          ++count;
          truncation = std::max(truncation, std::abs(truncated.rgba[p * 4 + k] - exact));
        }
      }
      e.render_vs_exact = render_error;
      e.rmse_vs_exact = count ? std::sqrt(squares / double(count)) : 0.0;
      e.truncation = truncation;
    }
    if (c.approximation) {
      e.bound = c.approximation->max_abs;
      if (e.truncation > e.bound && r.status == "pass") {
        r.status = "fail";
        r.attribution = "model/reference";
        r.message = fmt::format("the SH approximation differs from the exact lighting integral by {:.3g} > {:.3g} "
                                "([tolerance] approximation: {})",
                                e.truncation, e.bound, c.approximation->reason);
      }
    }
    r.sh = std::move(e);
  }

  const RunOptions& o_;
  const SceneSetup& scene_;
  const StoredReferences& stored_;
  Caches caches_;
  const NamedValues* sh_values_ = nullptr;          // the current SH group's light uniforms
  const std::map<std::string, std::shared_ptr<const Texture>>* sh_textures_ = nullptr;   // and its generated textures
  std::optional<ReferenceImage> sh_exact_;          // the current SH group's exact reference
  double area_ = 0;   // the current group's expected projected area, in pixels
  std::vector<PixelClass> classes_;   // the current group's reference, classified once for all its cells
  std::optional<Evidence> stored_evidence_;   // the current group's, against stored images
  std::map<std::string, std::vector<std::string>> other_sources_;   // by case/variant/language
};

}  // namespace

struct GroupRunner::Impl : GroupWork {
  using GroupWork::GroupWork;
};

GroupRunner::GroupRunner(const RunOptions& o, const SceneSetup& scene, const StoredReferences& stored)
    : impl_(std::make_unique<Impl>(o, scene, stored)) {}
GroupRunner::~GroupRunner() = default;

std::vector<CellResult> GroupRunner::run(const CellGroup& g) { return impl_->run(g); }

Result<StoredReferences> load_stored_references(const RunOptions& o, const std::vector<Case>& cases,
                                                const ToolVersions& tools) {
  StoredReferences stored;
  std::vector<std::string> dirs;
  if (!o.against_dir.empty()) dirs.push_back(o.against_dir);
  else
    for (const Case& c : cases)
      if (!c.reference_images.empty()) dirs.push_back(c.reference_images);
  for (const std::string& dir : dirs) {
    if (stored.runs.contains(dir)) continue;
    auto run = load_stored_run(dir, o.size);
    if (!run) return std::unexpected(Error(run.error()).in_stage(o.against_dir.empty() ? "case" : "--against"));
    stored.toolchain_notes[dir] = toolchain_difference(run->tools, tools);
    stored.runs.emplace(dir, std::move(*run));
  }
  return stored;
}


}  // namespace shaderbed
