// LUT bounds over the configurations a shape shows: a small (N.V, N.L) region gets a bound
// from that region, far below the whole table's, so a lookup half a texel off exceeds it
// there although it stays under the whole-table bound.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "lut/LookupTexture.h"
#include "lut/LutTolerance.h"

namespace shaderbed {
namespace {

TEST(LutDomain, BoundFollowsTheRegionAndCatchesAShiftedLookup) {
  const ModelParams p{{"lut_size", {64}}, {"roughness_sq", {0.5}}, {"diffuse", {1, 1, 1}}};
  auto lut = generate_lut("oren_nayar_angle", p);
  ASSERT_TRUE(lut) << lut.error().to_string();
  // A patch of a lit surface seen at a slant, as a cone's side shows it: N.V in
  // [0.2, 0.3], N.L in [0.85, 0.9], cosC = 1.
  LutDomain domain{.shape = "patch", .interior = {}, .band = {}};
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j)
      domain.interior.push_back(LutSample{.n_dot_l = 0.85 + 0.0025 * j, .n_dot_v = 0.2 + 0.005 * i, .cos_azimuth = 1});
  auto whole = lut_error_bound("oren_nayar_angle", p, *lut, 1.0);
  auto patch = lut_error_bound("oren_nayar_angle", p, *lut, domain);
  ASSERT_TRUE(whole && patch);
  EXPECT_LT(patch->max_abs, whole->max_abs / 10) << patch->derivation;
  EXPECT_GE(patch->band_max_abs, patch->max_abs);

  // The planted endpoint-texel lookup (tests/mutants/glsl/oren_nayar_lut_endpoint_texels.frag).
  const double b = 0.45 * 0.5 / (0.5 + 0.09);
  double shifted = 0;
  for (const LutSample& x : domain.interior) {
    const double n = 64, t[2] = {0.5 * x.n_dot_v + 0.5, 0.5 * x.n_dot_l + 0.5};
    const double wrong[2] = {(t[0] * (n - 1) + 0.5) / n, (t[1] * (n - 1) + 0.5) / n};
    const double view = std::acos(x.n_dot_v), light = std::acos(x.n_dot_l);
    const double exact = std::sin(std::max(view, light)) * std::tan(std::min(view, light));
    shifted = std::max(shifted, b * x.n_dot_l * std::abs(sample_linear(*lut, wrong) - exact));
  }
  EXPECT_GT(shifted, 3 * patch->max_abs) << "the wrong lookup must fail the bound for this region";
  EXPECT_LT(shifted, whole->max_abs) << "and the whole-table bound would have passed it";
}

TEST(LutDomain, UnlitConfigurationsAddNothing) {
  const ModelParams p{{"lut_size", {16}}, {"roughness_sq", {0.5}}};
  auto lut = generate_lut("oren_nayar_angle", p);
  ASSERT_TRUE(lut);
  // N.L = 1 has cosC = 0 (errata E8) and N.L = 0 is unlit: a cube's faces under the +Y light.
  LutDomain cube{.shape = "cube", .interior = {LutSample{.n_dot_l = 1, .n_dot_v = 0.4, .cos_azimuth = 0},
                                               LutSample{.n_dot_l = 0, .n_dot_v = 0.9, .cos_azimuth = 1}},
                 .band = {}};
  auto bound = lut_error_bound("oren_nayar_angle", p, *lut, cube);
  ASSERT_TRUE(bound);
  EXPECT_LT(bound->max_abs, 1e-6) << bound->derivation;
}

}  // namespace
}  // namespace shaderbed
