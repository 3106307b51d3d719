#include "lut/LookupTexture.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace shaderbed {
namespace {

Result<double> scalar(const ModelParams& p, const std::string& kind, const std::string& name) {
  auto it = p.find(name);
  if (it == p.end() || it->second.empty())
    return fail(ErrorStage::lut, fmt::format("LUT '{}' needs the parameter '{}'", kind, name));
  return it->second[0];
}

Result<uint32_t> size_param(const ModelParams& p, const std::string& kind, const std::string& name, uint32_t max) {
  auto v = scalar(p, kind, name);
  if (!v) return std::unexpected(v.error());
  if (!(*v >= 2 && *v <= max) || std::floor(*v) != *v)
    return fail(ErrorStage::lut, fmt::format("LUT '{}': {} = {} must be an integer in 2..{}", kind, name, *v, max));
  return uint32_t(*v);
}

double centre(uint32_t i, uint32_t n) { return (i + 0.5) / n; }

}  // namespace

Result<Texture> generate_lut(const std::string& kind, const ModelParams& params) {
  if (kind == "warn_power") {
    // Row j holds exponent j, column i the base u: u^j (Fig. 6.10, red channel only).
    auto w = size_param(params, kind, "lut_size", 4096);
    auto h = size_param(params, kind, "lut_rows", 1024);
    if (!w) return std::unexpected(w.error());
    if (!h) return std::unexpected(h.error());
    Texture t{.name = "lut", .dimensions = 2, .width = *w, .height = *h};
    t.texels.resize(size_t(*w) * *h);
    for (uint32_t j = 0; j < *h; ++j)
      for (uint32_t i = 0; i < *w; ++i) t.texels[size_t(j) * *w + i] = float(std::pow(centre(i, *w), double(j)));
    return t;
  }
  if (kind == "oren_nayar_angle") {
    // u -> N.V, v -> N.L in [-1, 1]; value sin(alpha) tan(beta) (Fill_OrenNayar_Texture).
    auto n = size_param(params, kind, "lut_size", 4096);
    if (!n) return std::unexpected(n.error());
    Texture t{.name = "lut", .dimensions = 2, .width = *n, .height = *n};
    t.texels.resize(size_t(*n) * *n);
    for (uint32_t j = 0; j < *n; ++j)
      for (uint32_t i = 0; i < *n; ++i) {
        const double view = std::acos(2 * centre(i, *n) - 1), light = std::acos(2 * centre(j, *n) - 1);
        t.texels[size_t(j) * *n + i] = float(std::sin(std::max(view, light)) * std::tan(std::min(view, light)));
      }
    return t;
  }
  if (kind == "ward_isotropic") {
    // (x, y, z) = (N.L, N.V, N.H) in (0, 1)^3 (Fill_WardIsotropic_Texture, with Ward's 4pi).
    auto n = size_param(params, kind, "lut_size", 512);
    auto sigma = scalar(params, kind, "roughness");
    if (!n) return std::unexpected(n.error());
    if (!sigma) return std::unexpected(sigma.error());
    const double s2 = *sigma * *sigma;
    Texture t{.name = "lut", .dimensions = 3, .width = *n, .height = *n, .depth = *n};
    t.texels.resize(size_t(*n) * *n * *n);
    for (uint32_t k = 0; k < *n; ++k) {
      const double z = centre(k, *n), tan2 = (1 - z * z) / (z * z);
      const double lobe = std::exp(-tan2 / s2) / (4 * std::numbers::pi * s2);
      for (uint32_t j = 0; j < *n; ++j)
        for (uint32_t i = 0; i < *n; ++i)
          t.texels[(size_t(k) * *n + j) * *n + i] = float(lobe / std::sqrt(centre(i, *n) * centre(j, *n)));
    }
    return t;
  }
  return fail(ErrorStage::lut, fmt::format("unknown LUT '{}' (known: warn_power, oren_nayar_angle, ward_isotropic)", kind));
}

double sample_linear(const Texture& t, const double* coords) {
  const uint32_t size[3] = {t.width, t.height, t.depth};
  uint32_t i0[3] = {0, 0, 0}, i1[3] = {0, 0, 0};
  double w[3] = {0, 0, 0};
  for (uint32_t d = 0; d < t.dimensions; ++d) {
    // Texel centres sit at (i + 0.5) / n; clamp-to-edge beyond the outer centres.
    const double x = std::clamp(coords[d] * size[d] - 0.5, 0.0, double(size[d] - 1));
    i0[d] = uint32_t(std::floor(x));
    i1[d] = std::min(i0[d] + 1, size[d] - 1);
    w[d] = x - i0[d];
  }
  auto texel = [&](uint32_t x, uint32_t y, uint32_t z) {
    return double(t.texels[(size_t(z) * t.height + y) * t.width + x]);
  };
  double result = 0;
  for (int corner = 0; corner < (1 << t.dimensions); ++corner) {
    double weight = 1;
    uint32_t at[3] = {0, 0, 0};
    for (uint32_t d = 0; d < t.dimensions; ++d) {
      const bool high = corner >> d & 1;
      weight *= high ? w[d] : 1 - w[d];
      at[d] = high ? i1[d] : i0[d];
    }
    if (weight != 0) result += weight * texel(at[0], at[1], at[2]);
  }
  return result;
}

}  // namespace shaderbed
