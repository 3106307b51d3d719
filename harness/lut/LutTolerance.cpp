#include "lut/LutTolerance.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include <fmt/format.h>

namespace shaderbed {
namespace {

double param(const ModelParams& p, const std::string& name, double fallback) {
  auto it = p.find(name);
  return it == p.end() || it->second.empty() ? fallback : it->second[0];
}

double max_channel(const ModelParams& p, const std::string& name) {
  auto it = p.find(name);
  if (it == p.end() || it->second.empty()) return 1;
  return *std::max_element(it->second.begin(), it->second.end());
}

// What the GPU's filter adds to exact linear interpolation: the weights are full float
// precision on lavapipe and llvmpipe (measured at most 1e-7 of the texel spread; see
// tests/vulkan/vulkan_texture_test.cpp), budgeted here as 1e-6 of the spread.
double filter_rounding(const Texture& t, const double* coords) {
  const uint32_t size[3] = {t.width, t.height, t.depth};
  double lo = INFINITY, hi = -INFINITY;
  uint32_t base[3] = {0, 0, 0};
  for (uint32_t d = 0; d < t.dimensions; ++d)
    base[d] = uint32_t(std::clamp(std::floor(coords[d] * size[d] - 0.5), 0.0, double(size[d] - 1)));
  for (int corner = 0; corner < (1 << t.dimensions); ++corner) {
    uint32_t at[3] = {0, 0, 0};
    for (uint32_t d = 0; d < t.dimensions; ++d) at[d] = std::min(base[d] + (corner >> d & 1), size[d] - 1);
    const double v = t.texels[(size_t(at[2]) * t.height + at[1]) * t.width + at[0]];
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return (hi - lo) * 1e-6;
}

}  // namespace

Result<LutErrorBound> lut_error_bound(const std::string& kind, const ModelParams& p, const Texture& lut,
                                      double light_scale) {
  double worst = 0, band = 0;
  // `interior` false: a configuration only the silhouette band can show (grazing view).
  auto consider = [&](double weight, double filtered, double exact, const double* coords, bool interior = true) {
    const double e = weight * (std::abs(filtered - exact) + filter_rounding(lut, coords));
    band = std::max(band, e);
    if (interior) worst = std::max(worst, e);
  };

  if (kind == "warn_power") {
    const double alpha = param(p, "warn_exponent", 10), rows = lut.height;
    constexpr int kSamples = 8192;
    for (int s = 0; s <= kSamples; ++s) {
      const double coords[2] = {double(s) / kSamples, (alpha + 0.5) / rows};
      consider(light_scale, sample_linear(lut, coords), std::pow(coords[0], alpha), coords);
    }
    return LutErrorBound{worst, worst, fmt::format("max over Lp.L in [0,1] of (I/d^2)max = {:.4g} times |bilinear LUT - u^{}| "
                                            "on a {}x{} LUT, plus filter rounding",
                                            light_scale, alpha, lut.width, lut.height)};
  }
  if (kind == "oren_nayar_angle") {
    const double s = param(p, "roughness_sq", 0.5), b = 0.45 * s / (s + 0.09), d = max_channel(p, "diffuse");
    // sin(a)tan(b) changes sign through +-infinity as N.L crosses 0 wherever N.V < N.L,
    // and bilinear filtering blends the texels on either side. Visible surfaces face the
    // eye, so the domain is N.V >= two texels; the back-facing and grazing sliver that
    // remains is in the silhouette band, judged there.
    const double min_view = 2.0 / lut.width;
    constexpr int kSamples = 1000;
    for (int i = 0; i <= kSamples; ++i)
      for (int j = 1; j <= kSamples; ++j) {
        const double nv = 2.0 * i / kSamples - 1, nl = double(j) / kSamples;   // N.L > 0: lit
        if (nv < 0) continue;
        const double view = std::acos(nv), light = std::acos(nl);
        const double exact = std::sin(std::max(view, light)) * std::tan(std::min(view, light));
        const double coords[2] = {0.5 * nv + 0.5, 0.5 * nl + 0.5};
        consider(d * b * nl, sample_linear(lut, coords), exact, coords, nv >= min_view);
      }
    return LutErrorBound{worst, band, fmt::format("max over N.V >= {:.4g} (band: N.V >= 0), N.L in (0,1] of D B (N.L) "
                                            "|bilinear LUT - sin(a)tan(b)| on a {}x{} LUT, plus filter rounding",
                                            min_view, lut.width, lut.height)};
  }
  if (kind == "ward_isotropic") {
    const double sigma = param(p, "roughness", 0.25), s2 = sigma * sigma, spec = max_channel(p, "specular");
    // Below the first texel centre in N.V the LUT clamps while the term grows like
    // 1/sqrt(N.V): that sliver (the last degree before the silhouette) is excluded and
    // judged by the silhouette band.
    const double min_view = 1.0 / lut.height, band_view = 0.25 / lut.height;
    constexpr int kSteps = 72;
    for (int a = 0; a < kSteps; ++a)
      for (int b = 0; b < kSteps; ++b)
        for (int c = 0; c <= kSteps; ++c) {
          const double tl = (a + 0.5) / kSteps * std::numbers::pi / 2, tv = (b + 0.5) / kSteps * std::numbers::pi / 2;
          const double phi = double(c) / kSteps * std::numbers::pi;
          const double lx = std::sin(tl), lz = std::cos(tl);
          const double vx = std::sin(tv) * std::cos(phi), vy = std::sin(tv) * std::sin(phi), vz = std::cos(tv);
          const double hx = lx + vx, hy = vy, hz = lz + vz, hn = std::sqrt(hx * hx + hy * hy + hz * hz);
          if (vz < band_view || hn == 0) continue;
          const double z = hz / hn, tan2 = (1 - z * z) / (z * z);
          const double exact = std::exp(-tan2 / s2) / (4 * std::numbers::pi * s2) / std::sqrt(lz * vz);
          const double coords[3] = {lz, vz, z};
          consider(spec * lz, sample_linear(lut, coords), exact, coords, vz >= min_view);
        }
    return LutErrorBound{worst, band, fmt::format("max over directions with N.V >= {:.4g} (band: >= {:.4g}) of S (N.L) "
                                            "|trilinear LUT - ward term| on a {}^3 LUT, plus filter rounding",
                                            min_view, band_view, lut.width)};
  }
  return fail(ErrorStage::lut, "no error bound for LUT '" + kind + "'");
}

Result<LutErrorBound> lut_error_bound(const std::string& kind, const ModelParams& p, const Texture& lut,
                                      const LutDomain& domain) {
  // What the shader multiplies the LUT term by and what the term should be, at one
  // configuration: e = weight * (|filtered - exact| + filter rounding); 0 where unlit.
  std::function<double(const LutSample&)> error_at;
  std::string term;
  if (kind == "warn_power") {
    const double alpha = param(p, "warn_exponent", 10), rows = lut.height;
    error_at = [&lut, alpha, rows](const LutSample& x) {
      const double u = std::clamp(x.spot_cos, 0.0, 1.0);
      const double weight = x.light_scale * std::max(x.n_dot_l, 0.0);
      if (weight <= 0) return 0.0;
      const double coords[2] = {u, (alpha + 0.5) / rows};
      return weight * (std::abs(sample_linear(lut, coords) - std::pow(u, alpha)) + filter_rounding(lut, coords));
    };
    term = fmt::format("D I/d^2 sat(N.Lp) |bilinear LUT - u^{}|, u = Lp.L", alpha);
  } else if (kind == "oren_nayar_angle") {
    const double s = param(p, "roughness_sq", 0.5), b = 0.45 * s / (s + 0.09), d = max_channel(p, "diffuse");
    error_at = [&lut, b, d](const LutSample& x) {
      const double weight = d * b * std::max(x.n_dot_l, 0.0) * std::clamp(x.cos_azimuth, 0.0, 1.0);
      if (weight <= 0) return 0.0;
      const double view = std::acos(std::clamp(x.n_dot_v, -1.0, 1.0)), light = std::acos(std::clamp(x.n_dot_l, -1.0, 1.0));
      const double exact = std::sin(std::max(view, light)) * std::tan(std::min(view, light));
      const double coords[2] = {0.5 * x.n_dot_v + 0.5, 0.5 * x.n_dot_l + 0.5};
      return weight * (std::abs(sample_linear(lut, coords) - exact) + filter_rounding(lut, coords));
    };
    term = "D B sat(N.L) cosC |bilinear LUT - sin(a)tan(b)| at (N.V, N.L)";
  } else if (kind == "ward_isotropic") {
    const double sigma = param(p, "roughness", 0.25), s2 = sigma * sigma, spec = max_channel(p, "specular");
    error_at = [&lut, s2, spec](const LutSample& x) {
      // The shader gates the term to N.L > 0 and N.V > 0 (errata E4), as the model does.
      if (x.n_dot_l <= 0 || x.n_dot_v <= 0) return 0.0;
      const double z = std::clamp(x.n_dot_h, 1e-9, 1.0), tan2 = (1 - z * z) / (z * z);
      const double exact = std::exp(-tan2 / s2) / (4 * std::numbers::pi * s2) / std::sqrt(x.n_dot_l * x.n_dot_v);
      const double coords[3] = {x.n_dot_l, x.n_dot_v, x.n_dot_h};
      return spec * x.n_dot_l * (std::abs(sample_linear(lut, coords) - exact) + filter_rounding(lut, coords));
    };
    term = "S (N.L) |trilinear LUT - ward term| at (N.L, N.V, N.H)";
  } else {
    return fail(ErrorStage::lut, "no error bound for LUT '" + kind + "'");
  }
  // The render looks up at its own fp32 dot products, not the reference's: each within
  // kDotError (about 100 ulp of a unit dot product: interpolation, normalize and dot),
  // so every configuration is also tried at the corners of that box.
  constexpr double kDotError = 1e-5;
  const auto perturbed_max = [&](const LutSample& x) {
    double e = error_at(x);
    for (int corner = 0; corner < 8; ++corner) {
      LutSample y = x;
      y.n_dot_l += corner & 1 ? kDotError : -kDotError;
      y.n_dot_v += corner & 2 ? kDotError : -kDotError;
      y.n_dot_h = std::min(1.0, y.n_dot_h + (corner & 4 ? kDotError : -kDotError));
      y.spot_cos += corner & 1 ? kDotError : -kDotError;
      e = std::max(e, error_at(y));
    }
    return e;
  };
  double interior = 0, band = 0;
  for (const LutSample& x : domain.interior) interior = std::max(interior, perturbed_max(x));
  for (const LutSample& x : domain.band) band = std::max(band, error_at(x));
  // The band's pixels may be matched at an interior neighbour: it is never tighter.
  band = std::max(band, interior);
  const std::string size = lut.dimensions == 3 ? fmt::format("{}^3", lut.width) : fmt::format("{}x{}", lut.width, lut.height);
  return LutErrorBound{interior, band,
                       fmt::format("max of {} on a {} LUT, plus filter rounding, over the {} {} interior pixels drawn "
                                   "(each with its dot products +-1e-5, the render's fp32 error) "
                                   "(band: {} configurations around its silhouette, extrapolated a pixel past the edge)",
                                   term, size, domain.interior.size(), domain.shape, domain.band.size())};
}

}  // namespace shaderbed
