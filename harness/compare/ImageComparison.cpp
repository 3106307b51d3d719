#include "compare/ImageComparison.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace shaderbed {
namespace {

double channel_error(const float* r, const double* ref) {
  double e = 0;
  for (int c = 0; c < 3; ++c) {
    const double d = std::abs(double(r[c]) - ref[c]);
    e = std::isnan(d) ? std::numeric_limits<double>::infinity() : std::max(e, d);
  }
  return e;
}

bool finite_pixel(const float* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

}  // namespace

std::vector<PixelClass> classify_pixels(const ReferenceImage& ref) {
  std::vector<PixelClass> classes(size_t(ref.width) * ref.height, PixelClass::background);
  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x) {
      int covered = 0, seen = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= ref.width || ny >= ref.height) continue;
          ++seen;
          covered += ref.coverage[size_t(ny) * ref.width + nx] ? 1 : 0;
        }
      const size_t i = size_t(y) * ref.width + x;
      classes[i] = covered == 0 ? PixelClass::background
                   : covered == seen && ref.coverage[i] ? PixelClass::interior
                                                        : PixelClass::silhouette;
    }
  return classes;
}

Comparison compare_images(const Image& render, const ReferenceImage& ref, const ComparisonThresholds& t) {
  Comparison out;
  if (render.width != ref.width || render.height != ref.height) {
    out.reason = fmt::format("render is {}x{}, reference {}x{}", render.width, render.height, ref.width, ref.height);
    return out;
  }
  const std::vector<PixelClass> classes = classify_pixels(ref);
  out.error = Image(render.width, render.height);
  double interior_sq = 0, band_sq = 0;

  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x) {
      const size_t i = size_t(y) * ref.width + x;
      const float* r = render.pixel(x, y);
      const double* q = &ref.rgba[i * 4];
      const bool drawn = render.coverage[i] != 0;
      out.error.coverage[i] = static_cast<uint8_t>(classes[i]);
      if (drawn && !finite_pixel(r)) ++out.nonfinite;
      float* e = out.error.pixel(x, y);
      for (int c = 0; c < 3; ++c) e[c] = float(std::abs(double(r[c]) - q[c]));
      e[3] = 1;

      switch (classes[i]) {
        case PixelClass::background:
          if (drawn) ++out.coverage_mismatch;
          break;
        case PixelClass::interior: {
          ++out.interior.pixels;
          if (!drawn) {
            ++out.coverage_mismatch;
            ++out.interior.bad_pixels;
            break;
          }
          const double err = channel_error(r, q);
          out.interior.max_abs = std::max(out.interior.max_abs, err);
          interior_sq += err * err;
          if (!(err <= t.interior_max_abs)) ++out.interior.bad_pixels;
          break;
        }
        case PixelClass::silhouette: {
          ++out.silhouette.pixels;
          // Best match over the 3x3 neighbourhood: same coverage, and if drawn, the
          // closest colour. A one-pixel edge shift is not an error; a wrong colour is.
          double best = std::numeric_limits<double>::infinity();
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const int nx = x + dx, ny = y + dy;
              if (nx < 0 || ny < 0 || nx >= ref.width || ny >= ref.height) continue;
              const size_t j = size_t(ny) * ref.width + nx;
              if ((ref.coverage[j] != 0) != drawn) continue;
              best = std::min(best, drawn ? channel_error(r, &ref.rgba[j * 4]) : 0.0);
            }
          if (std::isfinite(best)) {
            out.silhouette.max_abs = std::max(out.silhouette.max_abs, best);
            band_sq += best * best;
          } else {
            out.silhouette.max_abs = std::numeric_limits<double>::infinity();
          }
          if (!(best <= t.silhouette_max_abs)) ++out.silhouette.bad_pixels;
          break;
        }
      }
    }
  if (out.interior.pixels) out.interior.rmse = std::sqrt(interior_sq / out.interior.pixels);
  if (out.silhouette.pixels) out.silhouette.rmse = std::sqrt(band_sq / out.silhouette.pixels);
  out.psnr = out.interior.rmse > 0 ? 20.0 * std::log10(1.0 / out.interior.rmse) : std::numeric_limits<double>::infinity();

  if (out.interior.pixels == 0) out.reason = "reference covers no interior pixels (nothing to compare)";
  else if (out.nonfinite) out.reason = fmt::format("{} NaN/Inf pixels", out.nonfinite);
  else if (out.coverage_mismatch) out.reason = fmt::format("coverage differs at {} pixels", out.coverage_mismatch);
  else if (out.interior.bad_pixels)
    out.reason = fmt::format("{} interior pixels over {:.3g} (max {:.3g})", out.interior.bad_pixels, t.interior_max_abs,
                             out.interior.max_abs);
  else if (out.silhouette.bad_pixels)
    out.reason = fmt::format("{} silhouette pixels over {:.3g} (max {:.3g})", out.silhouette.bad_pixels,
                             t.silhouette_max_abs, out.silhouette.max_abs);
  out.pass = out.reason.empty();
  return out;
}

}  // namespace shaderbed
