#include <cmath>
#include <deque>
#include <filesystem>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/CacheSettings.h"
#include "prt/ShCase.h"
#include "report/CellVerdict.h"
#include "run/ReferenceKinds.h"
#include "run/ReferenceRender.h"

namespace shaderbed {
namespace {

// An SH case (harness/prt): the shape drawn with its per-vertex transfer streams, light
// coefficients and generated textures, judged against the truncated SH in double, and
// the truncation itself against the exact lighting integral where one exists.
struct ShInputs {
  explicit ShInputs(Result<ShPrepared> p) : prepared(std::move(p)) {}
  Result<ShPrepared> prepared;
  DrawAdditions additions;   // points into `prepared`
};

class ShReference final : public CellReference {
 public:
  ShReference(const GroupScene& g, std::shared_ptr<const ShInputs> inputs) : c_(*g.group.c), inputs_(std::move(inputs)) {
    // Its own mode even for a per-pixel reference (sweep): a per-vertex SH technique has no
    // per-pixel truncated SH, and its error against the exact integral is what a sweep charts.
    mode_ = g.group.variant->mode;
    if (!inputs_->prepared) {
      image_ = std::unexpected(inputs_->prepared.error());
      return;
    }
    const ShPrepared& p = *inputs_->prepared;
    image_ = render_reference(p.mesh, g.scene, c_, mode_, *p.truncated);
    if (p.exact)
      if (auto exact = render_reference(p.mesh, g.scene, c_, mode_, *p.exact)) exact_ = std::move(*exact);
  }

  ReferenceSource source() const override {
    return {"model", c_.model + ": the truncated SH in double" +
                         (mode_ == LightingMode::per_pixel ? std::string(" (per pixel)") : " (per vertex)")};
  }
  const Result<ReferenceImage>* group_image() const override { return &image_; }
  bool notes_textures() const override { return true; }

  // The render's error and the approximation's own (truncated SH in double against exact),
  // over the pixels both cover; a case's `[tolerance] approximation` bounds the latter.
  void judge(const Image& image, CellResult& r) const override {
    const ShPrepared& prepared = *inputs_->prepared;
    const ReferenceImage& truncated = *image_;
    CellResult::ShErrors e;
    e.summary = prepared.summary;
    e.precompute_ms = prepared.precompute_ms;
    e.bytes_per_vertex = double(prepared.bytes_per_vertex);
    if (exact_) {
      double render_error = 0, truncation = 0, squares = 0;
      size_t count = 0;
      for (size_t p = 0; p < exact_->coverage.size(); ++p) {
        if (!exact_->coverage[p] || !truncated.coverage[p] || !image.coverage[p]) continue;
        for (int k = 0; k < 3; ++k) {
          const double exact = exact_->rgba[p * 4 + k];
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
    if (c_.approximation) {
      e.bound = c_.approximation->max_abs;
      if (sh_approximation_exceeded(e) && r.status == CellStatus::pass) {
        r.status = CellStatus::fail;
        r.attribution = "model/reference";
        r.message = fmt::format("the SH approximation differs from the exact lighting integral by {:.3g} > {:.3g} "
                                "([tolerance] approximation: {})",
                                e.truncation, e.bound, c_.approximation->reason);
      }
    }
    r.sh = std::move(e);
  }

 private:
  const Case& c_;
  std::shared_ptr<const ShInputs> inputs_;
  LightingMode mode_;
  Result<ReferenceImage> image_ = fail(ErrorStage::reference, "not rendered");
  std::optional<ReferenceImage> exact_;
};

class ShKind final : public ReferenceKind {
 public:
  bool judges(const Case& c, const CellSettings&) const override { return is_sh_model(c.model); }

  Result<const DrawAdditions*> draw_inputs(const GroupScene& g) override {
    if (!is_sh_model(g.group.c->model)) return nullptr;
    const ShInputs& inputs = *inputs_for(g);
    if (!inputs.prepared) return std::unexpected(inputs.prepared.error());
    return &inputs.additions;
  }

  std::unique_ptr<CellReference> prepare(const GroupScene& g, GroupDrawer&) override {
    return std::make_unique<ShReference>(g, inputs_for(g));
  }

 private:
  // The precompute is kept per case, shape, light and parameters: a worker's groups share
  // it across variants, and the viewer's last few lights stay warm.
  std::shared_ptr<const ShInputs> inputs_for(const GroupScene& g) {
    const Case& c = *g.group.c;
    const glm::dvec3 light = g.scene.lights.direction;
    std::string key = fmt::format("{}|{}|{}|{:a},{:a},{:a}", c.path, c.name, g.mesh_key, light.x, light.y, light.z);
    for (const auto& [name, values] : c.params) key += fmt::format("|{}={}", name, fmt::join(values, ","));
    auto it = std::ranges::find(cache_, key, &Entry::first);
    if (it != cache_.end()) return it->second;
    if (cache_.size() == kKept) cache_.pop_front();
    const std::string root = cache_settings().root;
    auto inputs = std::make_shared<ShInputs>(
        prepare_sh(c, g.mesh, g.scene, root.empty() ? std::filesystem::path() : std::filesystem::path(root) / "sh"));
    if (inputs->prepared)
      inputs->additions = {&inputs->prepared->mesh, inputs->prepared->uniforms, inputs->prepared->textures};
    cache_.emplace_back(key, inputs);
    return inputs;
  }

  using Entry = std::pair<std::string, std::shared_ptr<const ShInputs>>;
  static constexpr size_t kKept = 8;
  std::deque<Entry> cache_;
};

}  // namespace

std::unique_ptr<ReferenceKind> sh_reference_kind() { return std::make_unique<ShKind>(); }

}  // namespace shaderbed
