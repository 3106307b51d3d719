#include <deque>

#include <fmt/format.h>

#include "compare/ExactDifference.h"
#include "run/CaseUniforms.h"
#include "run/ReferenceKinds.h"

namespace shaderbed {
namespace {

// A differential case's original shader, drawn by one backend and path (the case's
// `reference = {...}`): every cell of the group is judged against its render. When the
// original is one of the group's cells, that cell's own draw is the reference.
class OriginalReference final : public CellReference {
 public:
  OriginalReference(const GroupScene& g, GroupDrawer& drawer) : g_(g) {
    const CellGroup& group = g.group;
    const Case& c = *group.c;
    if (!c.reference_render) {   // the case loader requires one; kept from a crash all the same
      image_ = fail(ErrorStage::reference, "the case names no reference");
      return;
    }
    const RenderReference& original = *c.reference_render;
    label_ = fmt::format("{} {}/{}", to_string(original.language), original.backend, original.path);
    if (!original.variant.empty()) label_ += " (variant " + original.variant + ")";
    const auto error = [&](std::string message) {
      return std::unexpected(Error{.message = std::move(message), .file = c.path, .line = original.line, .stage = ErrorStage::reference});
    };
    if (!group.reference_cell) {
      image_ = error("the reference backend '" + original.backend + "' has no path '" + original.path + "'");
      return;
    }
    // Which of the group's cells draws the original, if the filters kept it.
    if (group.reference_variant == group.variant)
      for (size_t i = 0; i < group.cells.size(); ++i) {
        const PlannedCell& cell = group.cells[i];
        if (cell.language == group.reference_cell->language && cell.backend == group.reference_cell->backend &&
            cell.path == group.reference_cell->path)
          index_ = i;
      }
    CellResult r = drawer.row(*group.reference_cell, source());
    // As a cell of the run it is timed like the others; drawn only as the reference, once.
    const TimingRequest timing = index_ ? g.settings.timing : TimingRequest{.warmup = 0, .runs = 1};
    Result<Image> image = drawer.draw(*group.reference_variant, *group.reference_cell, timing, r);
    if (!image) {
      image_ = error("the original (" + label_ + ") could not be drawn: " + image.error().to_string());
      return;
    }
    // The original must itself look like the shape (coverage near the mesh's projected
    // area); a blank or misplaced original judges nothing.
    ReferenceImage reference = as_reference_image(*image);
    const Comparison itself = compare_images(*image, reference, {}, g.area);
    if (itself.degenerate || itself.blank || itself.interior.pixels == 0) {
      image_ = error("the original (" + label_ + ") is no reference: " + itself.reason);
      return;
    }
    if (index_) drawn_ = DrawnReferenceCell{std::move(r), std::move(*image)};
    image_ = std::move(reference);
  }

  ReferenceSource source() const override { return {"render", label_}; }
  const Result<ReferenceImage>* group_image() const override { return &image_; }
  bool notes_textures() const override { return false; }   // the original reads the same files

  std::optional<DrawnReferenceCell> take_drawn(size_t index) override {
    if (index_ != index || !drawn_) return std::nullopt;
    return std::exchange(drawn_, std::nullopt);
  }

  // The original drawn with each channel of each 8-bit image file it samples a stored step
  // off, one draw each: how far one step of the texel format moves its pixels.
  std::optional<TexelStepBound> texel_bound(GroupDrawer& drawer) const override {
    const CellGroup& group = g_.group;
    if (!image_ || !group.reference_cell) return std::nullopt;
    std::vector<std::pair<std::string, int>> steps;
    for (const auto& [name, entry] : group.c->textures.for_language(group.reference_cell->language)) {
      if (entry.files.empty()) continue;
      SamplerSettings settings = entry.settings.applied_to({});
      // Generated or stored levels may be blended: count the mip lerp unless the entry says otherwise.
      if (entry.mipmaps && !entry.settings.mip_filter) settings.mip_filter = MipFilter::linear;
      if (const int n = filter_rounding_steps(settings); n > 0) steps.emplace_back(name, n);
    }
    std::deque<Image> images;
    std::vector<SteppedDraw> draws;
    for (const auto& [name, n] : steps)
      for (int channel = 0; channel < 4; ++channel) {
        const TexelStep step{name, channel};
        CellResult scratch = drawer.row(*group.reference_cell, {});
        auto image = drawer.draw(*group.reference_variant, *group.reference_cell, {.warmup = 0, .runs = 1}, scratch,
                                 {.texel_step = &step});
        if (!image) break;   // not an 8-bit image file: its other channels are not either
        images.push_back(std::move(*image));
        draws.push_back({name, channel, &images.back()});
      }
    if (draws.empty()) return std::nullopt;
    return texel_step_bound(*image_, classify_pixels(*image_), draws, steps);
  }

  // The original drawn again with the light negated, its matrices transposed, its images
  // upside down, or half a pixel off.
  std::vector<Redrawn> counterfactuals(GroupDrawer& drawer) const override {
    std::vector<Redrawn> out;
    const CellGroup& group = g_.group;
    if (!group.reference_cell) return out;
    const auto redraw = [&](const Variation& variation) -> Result<ReferenceImage> {
      CellResult scratch = drawer.row(*group.reference_cell, {});
      auto image = drawer.draw(*group.reference_variant, *group.reference_cell, {.warmup = 0, .runs = 1}, scratch, variation);
      if (!image) return std::unexpected(image.error());
      return as_reference_image(*image);
    };
    SceneSetup negated = g_.scene;
    negated.lights.direction = -negated.lights.direction;
    out.push_back({redraw({.scene = &negated}), "negated_light", "the light vector negated (L → −L)"});
    if (const auto transposed = transposed_matrices(group.reference_cell->language))
      out.push_back({redraw({.bindings = &*transposed}), "transposed_matrices",
                     "its matrices in the other row/column convention (transposed)"});
    out.push_back({redraw({.flip_images = true}), "flipped_texture_v", "its textures upside down (v → 1 − v)"});
    // D3D9 put pixel centres on integers: a port that keeps (or adds) that offset draws
    // everything half a pixel off, in one of four directions.
    static const char* const kShifts[] = {"the geometry half a pixel right and up (D3D9 pixel centres)",
                                          "the geometry half a pixel left and up (D3D9 pixel centres)",
                                          "the geometry half a pixel right and down (D3D9 pixel centres)",
                                          "the geometry half a pixel left and down (D3D9 pixel centres)"};
    for (int k = 0; k < 4; ++k) {
      SceneSetup shifted = g_.scene;
      shifted.clip_offset = {(k % 2 ? -1.0 : 1.0) / g_.scene.width, (k / 2 ? -1.0 : 1.0) / g_.scene.height};
      out.push_back({redraw({.scene = &shifted}), "half_pixel_offset_redrawn", kShifts[k]});
    }
    return out;
  }

 private:
  // The case's bindings for `language` with every matrix in the other row/column
  // convention, or nothing when it binds no matrix.
  std::optional<BindingTable> transposed_matrices(Language language) const {
    const Case& c = *g_.group.c;
    const auto table = c.bindings.find(language);
    if (table == c.bindings.end()) return std::nullopt;
    const NamedValues values = bindable_values(g_.scene, c);
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

  GroupScene g_;
  std::string label_;
  std::optional<size_t> index_;
  std::optional<DrawnReferenceCell> drawn_;
  Result<ReferenceImage> image_ = fail(ErrorStage::reference, "not drawn");
};

class OriginalKind final : public ReferenceKind {
 public:
  bool judges(const Case& c, const CellSettings&) const override { return c.differential(); }
  std::unique_ptr<CellReference> prepare(const GroupScene& g, GroupDrawer& drawer) override {
    return std::make_unique<OriginalReference>(g, drawer);
  }
};

}  // namespace

std::unique_ptr<ReferenceKind> original_reference_kind() { return std::make_unique<OriginalKind>(); }

}  // namespace shaderbed
