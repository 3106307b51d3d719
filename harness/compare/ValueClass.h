#pragma once
// How the comparison stage sorts values that are not ordinary numbers: NaN and the
// infinities are kept apart from finite values and from each other.
#include <cmath>
#include <limits>

namespace shaderbed {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// 0 finite, 1 NaN, 2 +Inf, 3 -Inf (a float converts to double exactly, class and all).
inline int value_class(double v) {
  if (std::isfinite(v)) return 0;
  if (std::isnan(v)) return 1;
  return v > 0 ? 2 : 3;
}

// Whether a pixel's red, green and blue are all finite.
inline bool finite_rgb(const float* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }
inline bool finite_rgb(const double* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

}  // namespace shaderbed
