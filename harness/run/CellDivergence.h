#pragma once
// Where a failing port departs from what it is judged against (twin/Divergence.h): the
// port and its original, each drawn by its double twin, traced at the pixels where the
// cell fails and a spread of others, and their values matched by fingerprint. Done once
// per group, variant and language (the port's twin is the same on every backend and path).
#include <map>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "backends/twin/TwinRenderer.h"
#include "compare/ImageComparison.h"
#include "report/Results.h"
#include "run/CellPlan.h"
#include "run/CellReference.h"
#include "twin/Divergence.h"
#include "twin/PixelListing.h"

namespace shaderbed {

// The pixels a divergence is traced at: the `failing` interior pixels where the render is
// furthest from the reference, then `spread` more spaced evenly over the interior.
std::vector<twin::PixelAt> divergence_pixels(const Image& render, const ReferenceImage& reference,
                                             const std::vector<PixelClass>& classes, size_t failing = 12,
                                             size_t spread = 20);

// One pixel of a cell's shader, line by line (twin/PixelListing.h): what `shaderbed
// explain --pixel` prints and the viewer's inspector shows.
struct PixelExplanation {
  int x = 0, y = 0;
  std::string against;                   // "the original", "the model" (values matched), or "" (none)
  std::vector<twin::ListedLine> lines;   // the fragment stage's, at the pixel
  // Where the shader departs, over the same pixels: for a passing cell too (then, as a
  // rule, its output matches).
  std::optional<CellResult::Divergence> divergence;
};

class CellDivergence {
 public:
  CellDivergence();
  void begin_group() { found_.clear(); }
  // Failing cell `row` (its `render` judged against `image`, classified as `classes`),
  // traced at divergence_pixels: against the group's original when it has one, else
  // against the reference's named quantities (CellReference::quantities); nothing when it
  // shows none (a per-vertex model). Found once per variant and language: the pixels and
  // quantities are only asked for then.
  std::optional<CellResult::Divergence> locate(GroupDrawer& drawer, const CellGroup& group, const PlannedCell& cell,
                                               const CellResult& row, const Image& render, const ReferenceImage& image,
                                               const std::vector<PixelClass>& classes, const CellReference& reference);
  // Pixel (x, y) of cell `row`'s shader, by its double twin, with the original's matches
  // when the group has one, else the model's (`model` at `context`, x and y first: pixel
  // (x, y) must be context[0] then), matched over `context` as well as this pixel.
  Result<PixelExplanation> explain(GroupDrawer& drawer, const CellGroup& group, const PlannedCell& cell,
                                   const CellResult& row, int x, int y, std::span<const twin::PixelAt> context,
                                   std::span<const twin::Counterpart> model = {});

 private:
  // The divergence of the port's trace against `counterparts` (the original's, or the
  // model's when not `differential`), followed into the vertex stage, with its excerpts;
  // both twins' last draws are the cell's.
  CellResult::Divergence localise(const twin::ProgramTrace& port, std::span<const twin::Counterpart> counterparts,
                                  bool differential);
  // Both twins drawn for `cell` (the original's only when the group has one); the error
  // says which could not be.
  Result<void> draw_twins(GroupDrawer& drawer, const CellGroup& group, const PlannedCell& cell, const CellResult& row);

  BackendSlot port_slot_, original_slot_;   // two twins: both draws stay traceable
  TwinRenderer *port_ = nullptr, *original_ = nullptr;
  std::map<std::pair<const Variant*, Language>, std::optional<CellResult::Divergence>> found_;
};

}  // namespace shaderbed
