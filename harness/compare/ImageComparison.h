#pragma once
// Compares one render against the double-precision reference. Pixels are split by the
// reference's coverage into interior (the pixel and its 8 neighbours covered),
// background (none covered) and the one-pixel silhouette band between them. Interior
// pixels are judged strictly; in the band a pixel passes if it matches the reference at
// itself or at a neighbour (rasterisers legitimately differ on edges by a pixel).
//
// On top of the colour thresholds, failures no threshold can excuse:
//  - non-finite mismatch: a NaN/Inf channel where the reference has a finite value, or
//    the reverse, or a different non-finite (NaN vs +Inf). The same non-finite value in
//    both (the model itself yields NaN there) is agreement: counted, not failed.
//  - coverage: a reference-interior pixel not drawn or a background pixel drawn;
//  - blank or degenerate geometry: the number of drawn pixels differs from the
//    reference's, or either differs from the shape's projected area (computed from the
//    mesh, independently of both rasterisers), by more than coverage_allowance().
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/Image.h"
#include "report/CellVerdict.h"   // ComparisonThresholds, coverage_allowance
#include "report/Results.h"       // ValueCounts, CellMetrics (header-only model)

namespace shaderbed {

struct ReferenceImage {
  int width = 0;
  int height = 0;
  std::vector<double> rgba;        // width * height * 4
  std::vector<uint8_t> coverage;
};

enum class PixelClass : uint8_t { background, silhouette, interior };

// The interior/silhouette/background split of the reference coverage.
std::vector<PixelClass> classify_pixels(const ReferenceImage& reference);

struct RegionMetrics {
  size_t pixels = 0;
  size_t bad_pixels = 0;     // over the tolerance (or coverage / non-finite wrong)
  double max_abs = 0;        // largest per-channel |render - reference| (RGB); inf with a non-finite mismatch
  double rmse = 0;           // over the finite errors
};

struct Comparison {
  RegionMetrics interior;
  RegionMetrics silhouette;
  double psnr = 0;                 // interior, peak = 1
  size_t nonfinite = 0;            // NaN/Inf in drawn pixels of the render (matched or not)
  size_t nonfinite_mismatch = 0;   // pixels where exactly one side (or a different non-finite) is NaN/Inf
  size_t coverage_mismatch = 0;    // interior drawn as background or background drawn
  size_t covered_pixels = 0;             // drawn by the render
  size_t reference_covered_pixels = 0;   // covered in the reference
  double expected_area = 0;        // as given (0 = not checked)
  size_t allowed_coverage_difference = 0;   // coverage_allowance(silhouette.pixels)
  bool blank = false;              // the render draws nothing although the reference covers pixels
  bool degenerate = false;         // covered-pixel count off the reference's or the expected area
  bool uniform = false;            // every drawn pixel has the same colour (reported when failing)
  // The smallest thresholds with which this comparison would pass: the measured maxima,
  // or +inf for both when it fails for a reason no threshold excuses (coverage,
  // non-finite mismatch, blank/degenerate, size, empty reference).
  double min_passing_interior = 0;
  double min_passing_silhouette = 0;
  // The largest interior |render - reference| / (max_abs + max_rel |reference|): over 1
  // fails; with max_rel = 0 it is max_abs / the threshold.
  double interior_tolerance_share = 0;
  ValueCounts render_values;       // over the render's drawn pixels
  ValueCounts reference_values;    // over the reference's covered pixels
  bool pass = false;
  std::string reason;              // why it failed, "; "-separated, most basic first ("" = pass)
  Image error;                     // |render - reference| per channel (0 for a matched non-finite,
                                   // +inf for a mismatched one), coverage = PixelClass
};

// `expected_area`: the shape's projected area in pixels from projected_area_pixels()
// (scene/ProjectedArea.h) for the same transform and size; <= 0 skips that check.
// `classes`: classify_pixels(reference) when the caller already has it (every render of a
// group is compared with one reference); null = computed here.
Comparison compare_images(const Image& render, const ReferenceImage& reference, const ComparisonThresholds&,
                          double expected_area = 0, const std::vector<PixelClass>* classes = nullptr);

// The comparison's numbers in the results model (every CellMetrics field).
CellMetrics cell_metrics(const Comparison&);

// Value classes of an image's covered pixels (each pixel counted once per class that
// any of its RGB channels falls in; alpha is ignored).
ValueCounts count_values(const Image&);
ValueCounts count_values(const ReferenceImage&);

// Masks for looking, one colour per class (the first that applies, in this order):
// NaN magenta, +Inf red, -Inf blue, negative cyan, above one yellow; other covered
// pixels dark grey with a little of their brightness; coverage copied, so write_png()
// (ImageFiles.h) draws uncovered pixels in its background colour:
//   write_png(dir / "glsl-vulkan-spirv.values.png", value_mask(render));
Image value_mask(const Image&);
Image value_mask(const ReferenceImage&);

}  // namespace shaderbed
