#include "run/ReferenceKinds.h"

#include "reference/Reference.h"
#include "run/ReferenceRender.h"

namespace shaderbed {
namespace {

// A library model evaluated in double by the reference rasteriser (reference/).
class ModelReference final : public CellReference {
 public:
  explicit ModelReference(const GroupScene& g)
      : g_(g),
        mode_(g.settings.per_pixel_reference ? LightingMode::per_pixel : g.group.variant->mode),
        image_(render_reference(g.mesh, g.scene, *g.group.c, mode_)) {}

  ReferenceSource source() const override {
    return {"model", g_.group.c->model + (mode_ == LightingMode::per_pixel ? " (per pixel)" : " (per vertex)")};
  }
  const Result<ReferenceImage>* group_image() const override { return &image_; }
  bool notes_textures() const override { return true; }

  // The model re-rendered with the light or eye negated; per pixel also with the normal
  // left unnormalised, L and V from the vertex stage, or the facet's normal (two causes
  // public per-pixel shaders showed).
  std::vector<Redrawn> counterfactuals(GroupDrawer&) const override {
    const auto redraw = [&](const reference::Perturbation& p) { return render_reference(g_.mesh, g_.scene, *g_.group.c, mode_, p); };
    std::vector<Redrawn> out;
    out.push_back({redraw({.negate_light = true}), "negated_light", "the light vector negated (L → −L)"});
    out.push_back({redraw({.negate_eye = true}), "negated_eye", "the eye vector negated (V → −V)"});
    if (mode_ == LightingMode::per_pixel) {
      out.push_back({redraw({.unnormalised_normal = true}), "unnormalised_normal_model",
                     "the interpolated normal not renormalised"});
      out.push_back({redraw({.interpolated_light_eye = true}), "interpolated_light_eye",
                     "L and V normalised per vertex and interpolated, not renormalised per pixel"});
      out.push_back({redraw({.faceted_normal = true}), "faceted_normal",
                     "the flat facet normal instead of the interpolated one (a normal from screen-space "
                     "derivatives, cross(ddx(P), ddy(P)))"});
    }
    return out;
  }

 private:
  GroupScene g_;
  LightingMode mode_;
  Result<ReferenceImage> image_;
};

class ModelKind final : public ReferenceKind {
 public:
  bool judges(const Case& c, const CellSettings&) const override { return !c.differential(); }
  std::unique_ptr<CellReference> prepare(const GroupScene& g, GroupDrawer&) override {
    return std::make_unique<ModelReference>(g);
  }
};

}  // namespace

std::unique_ptr<ReferenceKind> model_reference_kind() { return std::make_unique<ModelKind>(); }

}  // namespace shaderbed
