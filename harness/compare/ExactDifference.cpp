#include "compare/ExactDifference.h"

#include <cmath>

namespace shaderbed {

ExactDifference exact_difference(const Image& image, const ReferenceImage& reference,
                                 const std::vector<PixelClass>& classes, const ChannelTolerance& tolerance) {
  ExactDifference d;
  const bool exact = !image.exact_rgba.empty();
  double sum_sq = 0;
  size_t channels = 0;
  for (int y = 0; y < reference.height && y < image.height; ++y)
    for (int x = 0; x < reference.width && x < image.width; ++x) {
      const size_t i = size_t(y) * reference.width + x;
      if (classes[i] != PixelClass::interior || !image.coverage[i] || !reference.coverage[i]) continue;
      ++d.pixels;
      bool finite = true;
      double worst = 0;
      for (int c = 0; c < 3; ++c) {
        const double a = exact ? image.exact_rgba[i * 4 + c] : image.rgba[i * 4 + c];
        const double b = reference.rgba[i * 4 + c];
        if (!std::isfinite(a) || !std::isfinite(b)) {
          finite = false;
          continue;
        }
        const double e = std::abs(a - b);
        const double allowed = tolerance.max_abs + tolerance.max_rel * std::abs(b);
        if (allowed > 0) d.tolerance_share = std::max(d.tolerance_share, e / allowed);
        sum_sq += e * e;
        ++channels;
        worst = std::max(worst, e);
      }
      if (!finite && d.nonfinite++ == 0) {
        d.nonfinite_x = x;
        d.nonfinite_y = y;
      }
      if (worst > d.max_abs || d.worst_x < 0) {
        d.max_abs = worst;
        d.worst_x = x;
        d.worst_y = y;
      }
    }
  d.rmse = channels ? std::sqrt(sum_sq / double(channels)) : 0;
  return d;
}

ReferenceImage as_reference_image(const Image& image) {
  if (!image.exact_rgba.empty()) return {image.width, image.height, image.exact_rgba, image.coverage};
  return {image.width, image.height, std::vector<double>(image.rgba.begin(), image.rgba.end()), image.coverage};
}

}  // namespace shaderbed
