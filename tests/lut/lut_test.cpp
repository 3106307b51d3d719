// CPU lookup textures: contents at texel centres, the reference linear filter, and
// error bounds that shrink as the LUT grows.
#include <cmath>

#include <gtest/gtest.h>

#include "lut/LookupTexture.h"
#include "lut/LutTolerance.h"

namespace shaderbed {
namespace {

TEST(Lut, WarnPowerHoldsPowersAtTexelCentres) {
  auto t = generate_lut("warn_power", {{"lut_size", {8}}, {"lut_rows", {4}}});
  ASSERT_TRUE(t) << t.error().to_string();
  ASSERT_EQ(t->width, 8u);
  ASSERT_EQ(t->height, 4u);
  EXPECT_FLOAT_EQ(t->texels[3 * 8 + 5], float(std::pow(5.5 / 8, 3)));
  EXPECT_FLOAT_EQ(t->texels[0 * 8 + 7], 1.0f);   // exponent 0
}

TEST(Lut, LinearSamplingHitsCentresBlendsAndClamps) {
  Texture t{.name = "t", .dimensions = 2, .width = 2, .height = 2, .texels = {0, 1, 2, 3}};
  const double centre[2] = {0.25, 0.75};
  EXPECT_DOUBLE_EQ(sample_linear(t, centre), 2.0);
  const double middle[2] = {0.5, 0.5};
  EXPECT_DOUBLE_EQ(sample_linear(t, middle), 1.5);
  const double outside[2] = {-3.0, 7.0};
  EXPECT_DOUBLE_EQ(sample_linear(t, outside), 2.0);
  Texture v{.name = "v", .dimensions = 3, .width = 2, .height = 2, .depth = 2, .texels = {0, 1, 2, 3, 4, 5, 6, 7}};
  const double cube_centre[3] = {0.5, 0.5, 0.5};
  EXPECT_DOUBLE_EQ(sample_linear(v, cube_centre), 3.5);
}

TEST(Lut, OrenNayarAngleTermMatchesTheFormula) {
  auto t = generate_lut("oren_nayar_angle", {{"lut_size", {16}}});
  ASSERT_TRUE(t);
  const double nv = 2 * (3.5 / 16) - 1, nl = 2 * (12.5 / 16) - 1;
  const double a = std::max(std::acos(nv), std::acos(nl)), b = std::min(std::acos(nv), std::acos(nl));
  EXPECT_NEAR(t->texels[12 * 16 + 3], std::sin(a) * std::tan(b), 1e-6);
}

TEST(Lut, ErrorBoundsFallAsTheLutGrows) {
  for (const char* kind : {"oren_nayar_angle", "ward_isotropic"}) {
    double previous = INFINITY;
    for (double size : {8.0, 16.0, 32.0}) {
      ModelParams p{{"lut_size", {size}}, {"roughness", {0.25}}, {"roughness_sq", {0.5}}};
      auto t = generate_lut(kind, p);
      ASSERT_TRUE(t) << t.error().to_string();
      auto bound = lut_error_bound(kind, p, *t, 1.0);
      ASSERT_TRUE(bound) << bound.error().to_string();
      EXPECT_LT(bound->max_abs, previous) << kind << " at " << size;
      EXPECT_GT(bound->max_abs, 0) << kind;
      previous = bound->max_abs;
    }
  }
}

TEST(Lut, BadParametersAreErrors) {
  EXPECT_FALSE(generate_lut("warn_power", {{"lut_size", {0}}, {"lut_rows", {4}}}));
  EXPECT_FALSE(generate_lut("warn_power", {{"lut_size", {8.5}}, {"lut_rows", {4}}}));
  auto missing = generate_lut("ward_isotropic", {{"lut_size", {8}}});
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("roughness"), std::string::npos);
  EXPECT_FALSE(generate_lut("teapot", {}));
}

}  // namespace
}  // namespace shaderbed
