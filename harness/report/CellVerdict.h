#pragma once
// How a judged cell's verdict follows from its numbers: the checks compare_images applies
// (compare/ImageComparison.h), stated over the metrics a report keeps (CellMetrics), so
// that a cell read back from a file (`merge`) is judged again by the same rules instead of
// trusting the status written beside them.
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "report/Results.h"

namespace shaderbed {

// How far a channel error is into its tolerance: d / (max_abs + max_rel |reference|);
// over 1 fails. A zero tolerance passes only an exact match.
inline double tolerance_share(double d, double reference, double max_abs, double max_rel) {
  const double allowed = max_abs + (std::isfinite(reference) ? max_rel * std::abs(reference) : 0.0);
  if (allowed > 0) return d / allowed;
  return d == 0 ? 0.0 : std::numeric_limits<double>::infinity();
}

// How many covered pixels a render (or the reference) may differ by from the reference
// (or the expected area): 8 + band / 8, where band = the reference's silhouette band
// pixels. The band runs along the whole outline, about 2.5 pixels per pixel of outline
// length, so band / 8 is about a third of a pixel of uniform growth or shrinkage of the
// outline; the 8 keeps tiny images (16..48 px) clear of pixel-centre sampling noise.
// Measured (see ImageComparison.cpp) the real differences are 0 between renders and
// reference and at most 0.45 of the allowance between reference and expected area.
size_t coverage_allowance(size_t silhouette_band_pixels);

// A channel passes when |render - reference| <= max_abs + max_rel * |reference|: an
// absolute floor near black plus a part relative to the pixel's magnitude (differential
// cases judge one fp32 render against another, whose rounding grows with the value).
struct ComparisonThresholds {
  double interior_max_abs = 0;
  double silhouette_max_abs = 0;
  double interior_max_rel = 0;
  double silhouette_max_rel = 0;
};

// The pixels over the tolerance, counted where the images are at hand (compare_images);
// a report keeps only their sum with the other bad pixels (CellMetrics::bad_pixels).
struct PixelsOver {
  size_t interior = 0, silhouette = 0;
  double interior_max = 0, silhouette_max = 0;   // the largest finite error among them
};

// Why a comparison with these metrics fails, most basic first; empty = it passes. With
// `over` the threshold reasons count the pixels over it; without (a cell read from a
// report) the bad pixels, the tolerance share and the maxima stand for them.
std::vector<std::string> failed_checks(const CellMetrics& m, const ComparisonThresholds& t, const PixelsOver* over = nullptr);

// The tolerance a cell was judged with.
ComparisonThresholds tolerance_of(const CellResult& r);

// Why a judged cell (pass or fail) fails by its own fields: failed_checks over its metrics
// and tolerance, and an SH cell's approximation over its bound (sh_approximation_exceeded).
// Empty = it passes.
std::vector<std::string> rejudge_failures(const CellResult& r);

// An SH cell whose truncated SH is further from the exact lighting integral than the
// case's [tolerance] approximation allows fails, whatever its render (run/ShReference).
bool sh_approximation_exceeded(const CellResult::ShErrors& e);

}  // namespace shaderbed
