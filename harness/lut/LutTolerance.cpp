#include "lut/LutTolerance.h"

#include <algorithm>
#include <cmath>
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
// tests/vulkan/VulkanTextureTest.cpp), budgeted here as 1e-6 of the spread.
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
  return fail("lut", "no error bound for LUT '" + kind + "'");
}

}  // namespace shaderbed
