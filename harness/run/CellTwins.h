#pragma once
// --twin: every drawn cell's render against the same shader executed by its twin
// (backends/twin, twin/) in the run's precision, and, when the cell has a reference image,
// the twin against it: the cell's error split into the render's own fp32 + driver part and
// the shader's formula. Its twin is drawn once per group, variant and language (the image
// does not depend on the GPU backend or path), and traced back to the source when the
// render has NaN/Inf or when a half twin departs from the render.
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "backends/twin/TwinRenderer.h"
#include "compare/ImageComparison.h"
#include "report/Results.h"
#include "run/CellPlan.h"
#include "run/CellReference.h"

namespace shaderbed {

// A failed cell's attribution refined by its twin figures: a render its exact shader does
// not reproduce while that shader passes is the driver's (or its path's); an "unclear" one
// whose exact shader fails as the render does is the SPIR-V's (the shader or its front end),
// not the driver's. Other attributions already say more and are kept.
void attribute_by_twin(CellResult& r);

class CellTwins {
 public:
  explicit CellTwins(const std::string& precision);   // "" = off
  bool enabled() const { return renderer_ != nullptr; }
  void begin_group() { drawn_.clear(); }
  // `row`: the cell's result so far (its identity names the twin's draw steps);
  // `reference`: the image the cell is judged against, null when it has none.
  CellResult::TwinFigures figures(GroupDrawer& drawer, const Variant& variant, const PlannedCell& cell,
                                  const CellResult& row, const Image& render, const ReferenceImage* reference);

 private:
  using Key = std::pair<const Variant*, Language>;
  // What every cell of one twin image shares, computed once.
  struct Drawn {
    Result<ReferenceImage> image = fail(ErrorStage::twin, "not drawn");   // at the twin's own precision
    std::vector<PixelClass> classes;   // classify_pixels(image)
    double ms = 0;
    double reference_max_abs = -1;     // the twin against the group's reference
    std::optional<double> self_error;  // the double twin against quad precision (once checked)
  };
  Drawn& twin_of(GroupDrawer& drawer, const Variant& variant, const PlannedCell& cell, const CellResult& row,
                 const ReferenceImage* reference);
  // Makes the renderer's last draw the one of `key`, whose pixels are then traced; false
  // when that draw fails.
  bool make_current(GroupDrawer& drawer, const Variant& variant, const PlannedCell& cell, const CellResult& row);

  std::string precision_;
  BackendSlot slot_;
  TwinRenderer* renderer_ = nullptr;
  std::map<Key, Drawn> drawn_;
  std::optional<Key> last_drawn_;   // what the renderer's last draw is
};

}  // namespace shaderbed
