#include "run/CellReference.h"

namespace shaderbed {

Result<ReferenceImage> CellReference::cell_image(const CellResult&) const {
  return fail(ErrorStage::reference, "the reference has one image for the whole group");
}

std::optional<DrawnReferenceCell> CellReference::take_drawn(size_t) { return std::nullopt; }

void CellReference::judge(const Image&, CellResult&) const {}

std::vector<Redrawn> CellReference::counterfactuals(GroupDrawer&) const { return {}; }

std::optional<TexelStepBound> CellReference::texel_bound(GroupDrawer&) const { return std::nullopt; }

std::vector<twin::Counterpart> CellReference::quantities(std::span<const twin::PixelAt>) const { return {}; }

Result<const DrawAdditions*> ReferenceKind::draw_inputs(const GroupScene&) { return nullptr; }

}  // namespace shaderbed
