#pragma once
// What the cells of one group (case x variant x shape) are judged against. Each kind of
// reference is one implementation — a library model in double, an SH case's lighting, the
// original shader's render, a stored run's images — which prepares once per group and then
// answers per cell. The runner and the viewer ask a reference what they need, never which
// kind it is; a new kind is one file and one line in run/ReferenceKinds.cpp. (As in
// VK-GL-CTS's ShaderRenderCase, where a case owns its evaluator, and as reference/'s
// LightingModel + ModelRegistry do for the models.)
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compare/ImageComparison.h"
#include "report/Results.h"
#include "run/CellDraw.h"
#include "run/CellPlan.h"
#include "run/RunOptions.h"
#include "run/TexelStepBound.h"
#include "scene/CaseFile.h"
#include "scene/Scene.h"
#include "twin/Divergence.h"

namespace shaderbed {

// The group a reference prepares for.
struct GroupScene {
  const CellGroup& group;
  const std::string& mesh_key;   // shape/tessellation: what per-shape work is kept by
  const Mesh& mesh;              // the shape
  const SceneSetup& scene;
  const CellSettings& settings;
  double area = 0;               // the shape's projected area, in pixels
};

// A re-draw of the original under a convention a port may get wrong (a counterfactual).
struct Variation {
  const SceneSetup* scene = nullptr;        // null: the group's
  const BindingTable* bindings = nullptr;   // null: the case's for the cell's language
  bool flip_images = false;                 // every 2D image file upside down
  const TexelStep* texel_step = nullptr;    // one channel of one 8-bit image a stored step off
};

// The draws a reference may ask of whoever runs the group (the runner, the viewer).
class GroupDrawer {
 public:
  virtual ~GroupDrawer() = default;
  // The row of a cell of the group's case before it is drawn: identity, thresholds, source.
  virtual CellResult row(const PlannedCell& cell, const ReferenceSource& source) const = 0;
  // Compiles, binds and draws `cell` of `variant` with the group's inputs; fills r's
  // compile and draw parts.
  virtual Result<Image> draw(const Variant& variant, const PlannedCell& cell, const TimingRequest& timing,
                             CellResult& r, const Variation& variation = {}) = 0;
};

// A render of the reference under a convention a port may get wrong.
struct Redrawn {
  Result<ReferenceImage> image;
  std::string name;     // stable id, e.g. "negated_light" (compare/ConventionFit.h)
  std::string detail;   // reads after "re-rendered with"
};

// A cell the reference drew while it prepared (the original, when it is one of the
// group's cells): its row and image.
struct DrawnReferenceCell {
  CellResult result;
  Image image;
};

class CellReference {
 public:
  virtual ~CellReference() = default;

  // How reports name the reference.
  virtual ReferenceSource source() const = 0;
  // The group's one image, or the error every cell gets; null for a reference with an
  // image per cell. With a group image the runner also attributes failures across the
  // group's renders and writes the image beside them.
  virtual const Result<ReferenceImage>* group_image() const = 0;
  // Cell r's own image, for a reference without a group image.
  virtual Result<ReferenceImage> cell_image(const CellResult& r) const;
  // Cell `index` of the group when the reference drew it already (taken once).
  virtual std::optional<DrawnReferenceCell> take_drawn(size_t index);
  // Its own rule, after a cell is compared (SH: the approximation's bound).
  virtual void judge(const Image& image, CellResult& r) const;
  // The reference again under each convention a port may get wrong, for the fits; asked
  // only when a cell failed.
  virtual std::vector<Redrawn> counterfactuals(GroupDrawer& drawer) const;
  // What the group's 8-bit textures add to every cell's tolerance, when the reference is a
  // render that samples them as the cells do (run/TexelStepBound.h); asked once per group
  // before its cells are judged. Nothing: no such texture, or a reference that reads none.
  virtual std::optional<TexelStepBound> texel_bound(GroupDrawer& drawer) const;
  // The reference's own named values at `pixels` on the way to its image (a model's N·L, D,
  // F, ...), which the divergence search matches a shader's values against
  // (run/CellDivergence.h); empty when it has none to show.
  virtual std::vector<twin::Counterpart> quantities(std::span<const twin::PixelAt> pixels) const;
  // Whether a cell's note on the image files it reads applies (CaseTextures::reference_note):
  // a model reads no texture.
  virtual bool notes_textures() const = 0;
};

// One kind of reference. It lives as long as a worker and keeps what its groups share.
class ReferenceKind {
 public:
  virtual ~ReferenceKind() = default;
  // Whether the kind judges the case (the first kind of the registry that does, does).
  virtual bool judges(const Case& c, const CellSettings& settings) const = 0;
  // What every draw of a case's group takes from the kind, whatever judges it (an SH
  // case's light coefficients, textures and mesh); null: nothing; an error: why no cell of
  // the group can be drawn at all (an SH precompute that failed).
  virtual Result<const DrawAdditions*> draw_inputs(const GroupScene& group);
  virtual std::unique_ptr<CellReference> prepare(const GroupScene& group, GroupDrawer& drawer) = 0;
};

}  // namespace shaderbed
