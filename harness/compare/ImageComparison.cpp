#include "compare/ImageComparison.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "compare/ValueClass.h"

// DESIGN: the coverage-count rule (blank and degenerate images).
// Counting drawn pixels catches what per-pixel masks cannot: a render that draws
// nothing (blank) or the wrong size and, with the expected area from the mesh, a
// reference that is itself wrong the same way as the renders (both wrong or both blank
// then no longer pass together). The allowance is tied to the outline length, because
// that is where legitimate differences live: rasterisers sampling pixel centres differ
// from each other, and from the exact area, only in pixels the outline crosses. The
// reference's silhouette band (pixels with covered and uncovered pixels in their 3x3
// neighbourhood) runs along the outline, about 2.5 px per px of outline (8/pi for a
// smooth curve, 2 for an axis-aligned edge), so allowance = 8 + band / 8 is about a
// third of a pixel of growth or shrinkage all along the outline, plus 8 px for tiny
// images.
//
// Measured (lambert and phong, pixel variant, every backend/path, sizes 16..512,
// Mesa 22.3 lavapipe and llvmpipe against the reference and projected_area_pixels):
//  - renders vs reference: identical counts on every shape and size (0 px);
//  - reference vs projected area (low tessellation, as rendered): at most 53 px at
//    256 (the cube: its vertical silhouette edges are pixel-column aligned, so
//    centre sampling errs the same way all along them): 0.40 of its allowance (134);
//    0.45 of it at worst (the cube at 32 px), typically under 0.2;
//  - at 256 px the allowance is 118 (cone) .. 148 (sphere) px: a 1 % scale change of
//    the geometry (2 % of the area) exceeds it on every shape; the sphere's high
//    tessellation has 490 px more area than its low one, so the expected area must
//    come from the mesh actually drawn.
// With the expected area passed, all 1120 cells of the library at 256 px still pass.
// A shift keeps the count: it is caught by the per-pixel coverage (two pixels or more)
// and by the interior colours (one pixel) instead.

namespace shaderbed {
namespace {

struct PixelError {
  double error;        // largest per-channel |r - q|; 0 for equal non-finite values, inf for unequal
  bool nonfinite_mismatch;
};

inline PixelError pixel_error(const float* r, const double* q) {
  double e = 0;
  bool mismatch = false;
  for (int c = 0; c < 3; ++c) {
    const double a = r[c], b = q[c];
    const double d = std::abs(a - b);
    if (std::isfinite(d)) {
      e = std::max(e, d);
    } else if (!(std::isfinite(a) && std::isfinite(b)) && value_class(a) != value_class(b)) {
      e = kInf;
      mismatch = true;
    }
    // Otherwise both are the same non-finite value: agreement.
  }
  return {e, mismatch};
}

template <typename Q>
inline double pixel_share(const double* d, const Q* q, double max_abs, double max_rel) {
  return std::max({tolerance_share(d[0], q[0], max_abs, max_rel), tolerance_share(d[1], q[1], max_abs, max_rel),
                   tolerance_share(d[2], q[2], max_abs, max_rel)});
}

template <typename T>
void add_values(ValueCounts& v, const T* p) {
  bool nan = false, pos_inf = false, neg_inf = false, negative = false, above_one = false;
  for (int c = 0; c < 3; ++c) {
    const double x = p[c];
    if (std::isnan(x)) nan = true;
    else if (std::isinf(x)) (x > 0 ? pos_inf : neg_inf) = true;
    else if (x < 0) negative = true;
    else if (x > 1) above_one = true;
  }
  v.nan += nan;
  v.pos_inf += pos_inf;
  v.neg_inf += neg_inf;
  v.negative += negative;
  v.above_one += above_one;
}

template <typename T>
void add_values_fast(ValueCounts& v, const T* p) {
  // Common case first: three finite values in [0, 1].
  if (p[0] >= 0 && p[0] <= 1 && p[1] >= 0 && p[1] <= 1 && p[2] >= 0 && p[2] <= 1) return;
  add_values(v, p);
}

template <typename T>
void mask_colour(const T* p, float* o) {
  bool nan = false, pos_inf = false, neg_inf = false, negative = false, above_one = false;
  for (int c = 0; c < 3; ++c) {
    const double x = p[c];
    if (std::isnan(x)) nan = true;
    else if (std::isinf(x)) (x > 0 ? pos_inf : neg_inf) = true;
    else if (x < 0) negative = true;
    else if (x > 1) above_one = true;
  }
  auto set = [o](float r, float g, float b) { o[0] = r, o[1] = g, o[2] = b, o[3] = 1; };
  if (nan) set(1, 0, 1);
  else if (pos_inf) set(1, 0, 0);
  else if (neg_inf) set(0, 0, 1);
  else if (negative) set(0, 1, 1);
  else if (above_one) set(1, 1, 0);
  else {
    const float luminance = float(std::clamp(0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2], 0.0, 1.0));
    const float g = 0.12f + 0.18f * luminance;
    set(g, g, g);
  }
}

}  // namespace

std::vector<PixelClass> classify_pixels(const ReferenceImage& ref) {
  // Separable 3x3 sums of covered and of uncovered in-image neighbours (pixels outside
  // the image count as neither): interior = no uncovered neighbour and covered itself,
  // background = no covered neighbour.
  const int w = ref.width, h = ref.height;
  const size_t n = size_t(w) * h;
  std::vector<uint8_t> covered_row(n), uncovered_row(n);
  for (int y = 0; y < h; ++y) {
    const uint8_t* c = &ref.coverage[size_t(y) * w];
    for (int x = 0; x < w; ++x) {
      int cov = 0, unc = 0;
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx;
        if (nx < 0 || nx >= w) continue;
        (c[nx] ? cov : unc) += 1;
      }
      covered_row[size_t(y) * w + x] = uint8_t(cov);
      uncovered_row[size_t(y) * w + x] = uint8_t(unc);
    }
  }
  std::vector<PixelClass> classes(n, PixelClass::background);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int cov = 0, unc = 0;
      for (int dy = -1; dy <= 1; ++dy) {
        const int ny = y + dy;
        if (ny < 0 || ny >= h) continue;
        cov += covered_row[size_t(ny) * w + x];
        unc += uncovered_row[size_t(ny) * w + x];
      }
      const size_t i = size_t(y) * w + x;
      classes[i] = cov == 0                       ? PixelClass::background
                   : unc == 0 && ref.coverage[i] ? PixelClass::interior
                                                 : PixelClass::silhouette;
    }
  return classes;
}

Comparison compare_images(const Image& render, const ReferenceImage& ref, const ComparisonThresholds& t,
                          double expected_area, const std::vector<PixelClass>* known_classes) {
  Comparison out;
  out.expected_area = expected_area > 0 ? expected_area : 0;
  out.min_passing_interior = out.min_passing_silhouette = kInf;
  if (render.width != ref.width || render.height != ref.height) {
    out.reason = fmt::format("render is {}x{}, reference {}x{}", render.width, render.height, ref.width, ref.height);
    return out;
  }
  const int w = ref.width, h = ref.height;
  std::vector<PixelClass> own_classes;
  const std::vector<PixelClass>* classes_of = known_classes;
  if (!classes_of || classes_of->size() != size_t(w) * h) {
    own_classes = classify_pixels(ref);
    classes_of = &own_classes;
  }
  const std::vector<PixelClass>& classes = *classes_of;
  out.error = Image(w, h);
  double interior_sq = 0, band_sq = 0;
  size_t interior_finite = 0, band_finite = 0;
  // Drawn pixels whose finite colour error is over the threshold, and the largest such error.
  size_t interior_over = 0, band_over = 0;
  double interior_finite_max = 0, band_finite_max = 0;
  double interior_share = 0;   // the largest d / allowed over the interior
  // Uniform-render detection and the reference's interior range (for the "blank output" note).
  const float* first_drawn = nullptr;
  bool uniform = true;
  double ref_lo[3] = {kInf, kInf, kInf}, ref_hi[3] = {-kInf, -kInf, -kInf};

  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      const float* r = render.pixel(x, y);
      const double* q = &ref.rgba[i * 4];
      const bool drawn = render.coverage[i] != 0;
      const PixelClass cls = classes[i];
      if (drawn) {
        ++out.covered_pixels;
        if (!finite_rgb(r)) ++out.nonfinite;
        add_values_fast(out.render_values, r);
        if (!first_drawn) first_drawn = r;
        else if (uniform && std::memcmp(first_drawn, r, 3 * sizeof(float)) != 0) uniform = false;
      }
      if (ref.coverage[i]) {
        ++out.reference_covered_pixels;
        add_values_fast(out.reference_values, q);
      }
      out.error.coverage[i] = static_cast<uint8_t>(cls);
      // Per channel |r - q| in double, once: the error image stores it as float, and an
      // interior pixel's error (pixel_error's definition) is its largest channel.
      double d[3];
      bool unequal_nonfinite = false;
      for (int c = 0; c < 3; ++c) {
        const double a = r[c], b = q[c];
        d[c] = std::abs(a - b);
        if (!std::isfinite(d[c])) {
          const bool same = value_class(a) == value_class(b);
          d[c] = same ? 0.0 : kInf;
          unequal_nonfinite |= !same;
        }
      }
      float* e = out.error.pixel(x, y);
      e[0] = float(d[0]), e[1] = float(d[1]), e[2] = float(d[2]), e[3] = 1;

      switch (cls) {
        case PixelClass::background:
          if (drawn) ++out.coverage_mismatch;
          break;
        case PixelClass::interior: {
          ++out.interior.pixels;
          for (int c = 0; c < 3; ++c)
            if (std::isfinite(q[c])) ref_lo[c] = std::min(ref_lo[c], q[c]), ref_hi[c] = std::max(ref_hi[c], q[c]);
          if (!drawn) {
            ++out.coverage_mismatch;
            ++out.interior.bad_pixels;
            break;
          }
          const PixelError pe{std::max({d[0], d[1], d[2]}), unequal_nonfinite};
          if (pe.nonfinite_mismatch) ++out.nonfinite_mismatch;
          out.interior.max_abs = std::max(out.interior.max_abs, pe.error);
          const double share = pe.nonfinite_mismatch ? kInf : pixel_share(d, q, t.interior_max_abs, t.interior_max_rel);
          interior_share = std::max(interior_share, share);
          if (std::isfinite(pe.error)) {
            interior_sq += pe.error * pe.error;
            ++interior_finite;
            interior_finite_max = std::max(interior_finite_max, pe.error);
            if (share > 1) ++interior_over;
          }
          if (!(share <= 1)) ++out.interior.bad_pixels;
          break;
        }
        case PixelClass::silhouette: {
          ++out.silhouette.pixels;
          // Best match over the 3x3 neighbourhood: same coverage, and if drawn, the
          // closest colour. A one-pixel edge shift is not an error; a wrong colour is.
          double best = kInf, best_share = kInf;
          bool any_drawn_neighbour = false, reference_matched = false;
          const bool check_reverse = ref.coverage[i] && !finite_rgb(q);
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const int nx = x + dx, ny = y + dy;
              if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
              const size_t j = size_t(ny) * w + nx;
              if (check_reverse && render.coverage[j]) {
                // The reference's non-finite value must show up in a render pixel nearby.
                any_drawn_neighbour = true;
                reference_matched = reference_matched || !pixel_error(&render.rgba[j * 4], q).nonfinite_mismatch;
              }
              if ((ref.coverage[j] != 0) != drawn) continue;
              if (!drawn) {
                best = best_share = 0;
                continue;
              }
              const double* qj = &ref.rgba[j * 4];
              const PixelError pj = pixel_error(r, qj);
              best = std::min(best, pj.error);
              if (!std::isfinite(pj.error)) continue;
              double dj[3];
              for (int c = 0; c < 3; ++c) dj[c] = std::isfinite(r[c] - qj[c]) ? std::abs(r[c] - qj[c]) : 0.0;
              best_share = std::min(best_share, pixel_share(dj, qj, t.silhouette_max_abs, t.silhouette_max_rel));
            }
          // Drawn and no covered neighbour agrees on finiteness (errors are finite
          // between finite values): a non-finite mismatch, as is a reference NaN/Inf
          // that no drawn render pixel nearby reproduces.
          const bool forward = drawn && !std::isfinite(best);
          const bool reverse = check_reverse && any_drawn_neighbour && !reference_matched;
          if (forward || reverse) ++out.nonfinite_mismatch;
          if (std::isfinite(best)) {
            band_sq += best * best;
            ++band_finite;
            band_finite_max = std::max(band_finite_max, best);
            if (best_share > 1) ++band_over;
          }
          out.silhouette.max_abs = std::max(out.silhouette.max_abs, reverse ? kInf : best);
          if (!(best_share <= 1) || reverse) ++out.silhouette.bad_pixels;
          break;
        }
      }
    }
  if (interior_finite) out.interior.rmse = std::sqrt(interior_sq / interior_finite);
  if (band_finite) out.silhouette.rmse = std::sqrt(band_sq / band_finite);
  out.psnr = out.interior.rmse > 0 ? 20.0 * std::log10(1.0 / out.interior.rmse) : kInf;
  out.uniform = out.covered_pixels > 1 && uniform;

  // Coverage counts: the render against the reference and the mesh's projected area,
  // and the reference against the projected area.
  const size_t allow = coverage_allowance(out.silhouette.pixels);
  out.allowed_coverage_difference = allow;
  auto off = [allow](double a, double b) { return std::abs(a - b) > double(allow); };
  const double covered = double(out.covered_pixels), ref_covered = double(out.reference_covered_pixels);
  out.blank = out.covered_pixels == 0 && out.reference_covered_pixels > 0;
  out.degenerate = off(covered, ref_covered) || (out.expected_area > 0 && off(covered, out.expected_area)) ||
                   (out.expected_area > 0 && off(ref_covered, out.expected_area));
  out.interior_tolerance_share = interior_share;

  // The verdict from the metrics, by the rules `merge` judges a cell read back with.
  const PixelsOver over{interior_over, band_over, interior_finite_max, band_finite_max};
  std::vector<std::string> reasons = failed_checks(cell_metrics(out), t, &over);
  if (!reasons.empty() && out.uniform) {
    bool reference_varies = false;
    for (int c = 0; c < 3; ++c) reference_varies = reference_varies || ref_hi[c] - ref_lo[c] > t.interior_max_abs;
    if (reference_varies)
      reasons.push_back(fmt::format("blank output: every drawn pixel is ({:.3g}, {:.3g}, {:.3g})", first_drawn[0],
                                    first_drawn[1], first_drawn[2]));
  }
  for (const std::string& s : reasons) out.reason += (out.reason.empty() ? "" : "; ") + s;
  out.pass = out.reason.empty();

  const bool threshold_independent = out.interior.pixels == 0 || out.blank || out.degenerate ||
                                     out.nonfinite_mismatch || out.coverage_mismatch;
  if (!threshold_independent) {
    out.min_passing_interior = out.interior.max_abs;
    out.min_passing_silhouette = out.silhouette.max_abs;
  }
  return out;
}

CellMetrics cell_metrics(const Comparison& c) {
  CellMetrics m;
  m.max_abs = c.interior.max_abs;
  m.rmse = c.interior.rmse;
  m.psnr = c.psnr;
  m.bad_pixels = c.interior.bad_pixels + c.silhouette.bad_pixels;
  m.nonfinite = c.nonfinite;
  m.nonfinite_mismatch = c.nonfinite_mismatch;
  m.coverage_mismatch = c.coverage_mismatch;
  m.silhouette_max_abs = c.silhouette.max_abs;
  m.interior_pixels = c.interior.pixels;
  m.silhouette_pixels = c.silhouette.pixels;
  m.covered_pixels = c.covered_pixels;
  m.reference_covered_pixels = c.reference_covered_pixels;
  m.expected_area = c.expected_area;
  m.min_passing_interior = c.min_passing_interior;
  m.min_passing_silhouette = c.min_passing_silhouette;
  m.tolerance_share = c.interior_tolerance_share;
  m.render_values = c.render_values;
  m.reference_values = c.reference_values;
  return m;
}

ValueCounts count_values(const Image& image) {
  ValueCounts v;
  for (size_t i = 0; i < image.coverage.size(); ++i)
    if (image.coverage[i]) add_values_fast(v, &image.rgba[i * 4]);
  return v;
}

ValueCounts count_values(const ReferenceImage& image) {
  ValueCounts v;
  for (size_t i = 0; i < image.coverage.size(); ++i)
    if (image.coverage[i]) add_values_fast(v, &image.rgba[i * 4]);
  return v;
}

Image value_mask(const Image& image) {
  Image mask(image.width, image.height);
  mask.coverage = image.coverage;
  for (size_t i = 0; i < mask.coverage.size(); ++i) mask_colour(&image.rgba[i * 4], &mask.rgba[i * 4]);
  return mask;
}

Image value_mask(const ReferenceImage& image) {
  Image mask(image.width, image.height);
  mask.coverage = image.coverage;
  for (size_t i = 0; i < mask.coverage.size(); ++i) mask_colour(&image.rgba[i * 4], &mask.rgba[i * 4]);
  return mask;
}

}  // namespace shaderbed
