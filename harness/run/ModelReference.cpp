#include "run/ReferenceKinds.h"

#include <map>

#include "reference/ModelQuantities.h"
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

  // The model's named quantities per pixel (reference/ModelQuantities.h), one counterpart
  // each; per-vertex shading interpolates colours only, so it has none but its own.
  std::vector<twin::Counterpart> quantities(std::span<const twin::PixelAt> pixels) const override {
    if (mode_ != LightingMode::per_pixel) return {};
    std::vector<std::pair<int, int>> at;
    for (const twin::PixelAt& p : pixels) at.emplace_back(p.x, p.y);
    const Case& c = *g_.group.c;
    auto values = reference::model_quantities(reference_scene(g_.mesh, g_.scene, c), c.model, c.params, at);
    if (!values) return {};
    std::vector<twin::Counterpart> out;
    std::map<std::string, size_t> index;
    for (size_t p = 0; p < values->size(); ++p)
      for (const reference::NamedQuantity& q : (*values)[p]) {
        auto [it, added] = index.try_emplace(q.name, out.size());
        const auto slots = uint32_t(q.values.size());
        if (added)
          out.push_back({"", 0, q.name, slots, std::vector<double>(pixels.size() * slots, 0.0),
                         std::vector<uint8_t>(pixels.size(), 0), true});
        twin::Counterpart& cp = out[it->second];
        if (cp.slots != slots) continue;
        std::copy(q.values.begin(), q.values.end(), cp.values.begin() + std::ptrdiff_t(p * slots));
        cp.present[p] = 1;
      }
    // The case's parameters, which the shader reads from its uniforms.
    for (const auto& [name, value] : c.params) {
      twin::Counterpart cp{"", 0, name, uint32_t(value.size()), {}, std::vector<uint8_t>(pixels.size(), 1), true};
      for (size_t p = 0; p < pixels.size(); ++p) cp.values.insert(cp.values.end(), value.begin(), value.end());
      out.push_back(std::move(cp));
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
