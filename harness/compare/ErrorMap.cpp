#include "compare/ErrorMap.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "compare/ImageComparison.h"
#include "imageio/ImageIoModule.h"
#include "report/ErrorScale.h"

namespace shaderbed {
namespace {

// write_png()'s colour for uncovered pixels (compare/ImageFiles.cpp), so the shape's
// outline reads the same in the render and in its error map.
constexpr uint8_t kMapBackground[3] = {26, 28, 36};

double largest_channel(const float* e) { return std::max({double(e[0]), double(e[1]), double(e[2])}); }

}  // namespace

ErrorMap error_map(const Image& error, double threshold) {
  ErrorMap map{error.width, error.height, std::vector<uint8_t>(size_t(error.width) * error.height * 3), {}};
  const size_t n = size_t(error.width) * error.height;
  const auto cls = [&](size_t i) { return error.coverage.empty() ? PixelClass::interior : PixelClass(error.coverage[i]); };
  // The scale's top: the worst finite interior error (the first such pixel), or the threshold.
  ErrorMapScale& s = map.scale;
  for (size_t i = 0; i < n; ++i) {
    if (cls(i) != PixelClass::interior) continue;
    const double e = largest_channel(&error.rgba[i * 4]);
    if (std::isfinite(e) && (s.peak_x < 0 || e > s.peak)) {
      s.peak = e;
      s.peak_x = int(i % size_t(error.width));
      s.peak_y = int(i / size_t(error.width));
    }
  }
  s.top = std::max(s.peak, threshold);
  if (!(s.top > 0)) s.top = std::numeric_limits<double>::min();   // all zero: every pixel at the bottom
  for (size_t i = 0; i < n; ++i) {
    uint8_t* o = &map.rgb[i * 3];
    if (cls(i) == PixelClass::background) {
      std::copy(kMapBackground, kMapBackground + 3, o);
      continue;
    }
    const double e = largest_channel(&error.rgba[i * 4]);
    const Rgb8 c = std::isfinite(e) ? error_scale_colour(e / s.top) : kErrorNonFinite;
    o[0] = c.r, o[1] = c.g, o[2] = c.b;
  }
  return map;
}

Result<void> write_error_map(const std::string& path, const ErrorMap& map) {
  return write_image_file(path, map.width, map.height, 3, PixelType::uint8, map.rgb.data());
}

}  // namespace shaderbed
