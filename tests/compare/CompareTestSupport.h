#pragma once
// Synthetic images for the comparison tests: a shaded disc as the reference, renders
// made from it (copied, shifted, scaled, blanked, poisoned with NaN) as real pixel data.
#include <cmath>
#include <functional>
#include <numbers>

#include "compare/ImageComparison.h"
#include "core/Image.h"

namespace shaderbed::compare_test {

constexpr int kSize = 64;

// A smooth shade: varies across the image by about 0.25 (1/256 per pixel at most), well
// inside [0, 1].
inline double shade(double x, double y, int c) { return 0.3 + 0.1 * c + 0.002 * x + 0.0015 * y; }

inline bool in_disc(double x, double y, double cx, double cy, double r) {
  return (x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r;
}

// Disc of radius r centred at (cx, cy) in pixels, sampled at pixel centres.
inline ReferenceImage disc_reference(double r = 20.0, double cx = 32.0, double cy = 32.0, int size = kSize) {
  ReferenceImage ref{size, size, std::vector<double>(size_t(size) * size * 4, 0.0),
                     std::vector<uint8_t>(size_t(size) * size, 0)};
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const size_t i = size_t(y) * size + x;
      if (!in_disc(x + 0.5, y + 0.5, cx, cy, r)) continue;
      ref.coverage[i] = 1;
      for (int c = 0; c < 3; ++c) ref.rgba[i * 4 + c] = shade(x, y, c);
      ref.rgba[i * 4 + 3] = 1;
    }
  return ref;
}

// The same kind of disc as a render (float), optionally with a colour transform.
inline Image disc_render(double r = 20.0, double cx = 32.0, double cy = 32.0, int size = kSize,
                         const std::function<double(double, int)>& colour = {}) {
  Image im(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      if (!in_disc(x + 0.5, y + 0.5, cx, cy, r)) continue;
      im.coverage[im.index(x, y)] = 1;
      float* p = im.pixel(x, y);
      for (int c = 0; c < 3; ++c) p[c] = float(colour ? colour(shade(x, y, c), c) : shade(x, y, c));
      p[3] = 1;
    }
  return im;
}

// The reference's pixels as a float render, with its coverage.
inline Image copy_of(const ReferenceImage& ref) {
  Image im(ref.width, ref.height);
  for (size_t i = 0; i < ref.rgba.size(); ++i) im.rgba[i] = float(ref.rgba[i]);
  im.coverage = ref.coverage;
  return im;
}

inline double disc_area(double r) { return std::numbers::pi * r * r; }

}  // namespace shaderbed::compare_test
