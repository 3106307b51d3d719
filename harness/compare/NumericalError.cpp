#include "compare/NumericalError.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "compare/ValueClass.h"

namespace shaderbed {
namespace {

// Maps a float onto a line of integers where neighbouring floats differ by 1 and the
// order is kept across the sign (sign-magnitude to two's complement offset).
int64_t ordered(float f) {
  const int32_t bits = std::bit_cast<int32_t>(f);
  return bits >= 0 ? int64_t(bits) : -int64_t(bits & 0x7fffffff);
}

}  // namespace

double relative_error(double render, double reference, double floor) {
  if (!std::isfinite(render) || !std::isfinite(reference)) {
    const bool same = (std::isnan(render) && std::isnan(reference)) || render == reference;
    return same ? 0.0 : std::numeric_limits<double>::infinity();
  }
  return std::abs(render - reference) / std::max(std::abs(reference), floor);
}

uint64_t ulp_distance(float a, float b) {
  if (std::isnan(a) || std::isnan(b)) return std::numeric_limits<uint64_t>::max();
  const int64_t d = ordered(a) - ordered(b);
  return uint64_t(d < 0 ? -d : d);
}

NumericalError numerical_error(const Image& render, std::span<const double> reference,
                               std::span<const PixelJudgement> judgement, double floor) {
  NumericalError e;
  e.floor = floor;
  const size_t n = size_t(render.width) * render.height;
  for (size_t i = 0; i < n && i < judgement.size() && (i + 1) * 4 <= reference.size(); ++i) {
    if (judgement[i] == PixelJudgement::skipped) continue;
    ++e.pixels;
    const float* r = &render.rgba[i * 4];
    const double* ref = &reference[i * 4];
    const bool render_finite = finite_rgb(r), reference_finite = finite_rgb(ref);
    if (!render_finite) {
      ++e.render_nonfinite;
      if (std::isnan(r[0]) || std::isnan(r[1]) || std::isnan(r[2])) ++e.render_nan;
      else ++e.render_inf;
    }
    if (!reference_finite) ++e.reference_nonfinite;
    if (judgement[i] == PixelJudgement::undefined) continue;
    if (render_finite != reference_finite) ++e.nonfinite_mismatch;
    if (!render_finite || !reference_finite || judgement[i] != PixelJudgement::measured) continue;
    ++e.measured_pixels;
    for (int c = 0; c < 3; ++c) {
      const double rel = relative_error(r[c], ref[c], floor);
      if (e.max_relative_pixel < 0 || rel > e.max_relative) {
        e.max_relative = rel;
        e.max_relative_pixel = int(i);
      }
      if (std::abs(ref[c]) < floor) continue;
      const uint64_t ulps = ulp_distance(r[c], float(ref[c]));
      if (e.max_ulps_pixel < 0 || ulps > e.max_ulps) {
        e.max_ulps = ulps;
        e.max_ulps_pixel = int(i);
      }
    }
  }
  return e;
}

}  // namespace shaderbed
