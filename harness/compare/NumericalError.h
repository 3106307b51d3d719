#pragma once
// Numerical error of an fp32 render against a double reference, for the hard-case suite
// (docs/hard-cases.md): non-finite counts on each side, the largest relative error and
// the largest distance in float ULPs.
//
// Non-finite values are counted over every judged pixel. The error metrics cover only
// the pixels a caller marks as measured (e.g. not on a discontinuity of the model, where
// the fp32 rounding of a dot decides the branch) and where both values are finite:
//  - relative error |render - ref| / max(|ref|, floor); the floor keeps values near 0
//    (where any absolute error is an infinite relative one) from dominating;
//  - ULPs between the render and (float)ref, only where |ref| >= floor: below it the
//    ULP scale of a value near 0 is no measure of accuracy.
#include <cstddef>
#include <cstdint>
#include <span>

#include "core/Image.h"

namespace shaderbed {

// The default floor: colours in the library are of order 1, so 1e-3 treats an absolute
// error of 1e-9 on a value near 0 as a relative error of 1e-6.
constexpr double kRelativeErrorFloor = 1e-3;

// |render - reference| / max(|reference|, floor); +inf when either side is non-finite
// (unless both are the same non-finite, then 0).
double relative_error(double render, double reference, double floor = kRelativeErrorFloor);

// Distance between two floats in units in the last place: the number of representable
// floats between them (0 for equal values, +0 and -0 equal). UINT64_MAX if either is NaN.
uint64_t ulp_distance(float a, float b);

enum class PixelJudgement : uint8_t {
  skipped,        // not part of the comparison (background)
  undefined,      // the model has no value here (e.g. a point light at distance 0): the
                  // render's NaN/Inf are counted, any value is accepted
  finite_only,    // counted for NaN/Inf only
  measured,       // NaN/Inf counted and the error measured
};

struct NumericalError {
  size_t pixels = 0;               // judged (all but skipped)
  size_t measured_pixels = 0;      // whose error entered the maxima
  size_t render_nonfinite = 0;     // pixels with a NaN or Inf channel (RGB) in the render
  size_t render_nan = 0;
  size_t render_inf = 0;
  size_t reference_nonfinite = 0;  // where the model itself has no finite value
  size_t nonfinite_mismatch = 0;   // render NaN/Inf where the reference is finite, or the reverse
  double max_relative = 0;
  int max_relative_pixel = -1;     // index (y * width + x) of that pixel, -1 if none
  uint64_t max_ulps = 0;
  int max_ulps_pixel = -1;
  double floor = kRelativeErrorFloor;
};

// `reference` is width*height*4 doubles (RGBA, alpha ignored), `judgement` width*height.
NumericalError numerical_error(const Image& render, std::span<const double> reference,
                               std::span<const PixelJudgement> judgement, double floor = kRelativeErrorFloor);

}  // namespace shaderbed
