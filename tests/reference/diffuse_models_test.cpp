// Minnaert and Oren-Nayar (docs/models.md) at hand-computed configurations, in the local
// frame of evaluate(): N = +z, directions by polar angle from N (and azimuth).
#include <gtest/gtest.h>

#include <cmath>

#include "ModelTestSupport.h"

namespace reference {
namespace {

using namespace testing;

const glm::dvec3 rough_diffuse{0.8, 0.6, 0.4};
const double cos30deg = std::sqrt(3.0) / 2;

// ---- minnaert: D (sat(N·V) sat(N·L))^k sat(N·L), k = minnaert_power (E5, E10) ----------

const Params minnaert{{"diffuse", to_param(rough_diffuse)}, {"minnaert_power", {0.8}}};

TEST(Minnaert, LightAndEyeAlongTheNormalIsTheDiffuseColour) {
  expect_colour_near(eval("minnaert", minnaert, z_axis, z_axis), rough_diffuse);
}

TEST(Minnaert, DarkensTowardTheLimb) {
  // N·L = 1/2, N·V = 1: D 0.5^0.8 0.5.
  expect_colour_near(eval("minnaert", minnaert, direction(60), z_axis), std::pow(0.5, 0.8) * 0.5 * rough_diffuse);
  // N·L = 1/2, N·V = cos 30: D (cos30 / 2)^0.8 / 2 < the above: the limb darkens.
  expect_colour_near(eval("minnaert", minnaert, direction(60), direction(30, 90)),
                     std::pow(cos30deg * 0.5, 0.8) * 0.5 * rough_diffuse);
}

TEST(Minnaert, IsTheClassicFormWithMEqualToPowerPlusOne) {
  // E5: D ((N·L)(N·V))^k (N·L) = D (N·L)^m (N·V)^(m-1) with m = k + 1 (Fig. 5.24 times the
  // irradiance).
  const double m = 1.8, n_dot_l = std::cos(glm::radians(40.0)), n_dot_v = std::cos(glm::radians(70.0));
  expect_colour_near(eval("minnaert", minnaert, direction(40, 10), direction(70, 200)),
                     std::pow(n_dot_l, m) * std::pow(n_dot_v, m - 1) * rough_diffuse);
}

TEST(Minnaert, PowerZeroIsLambert) {
  const Params lambertian{{"diffuse", to_param(rough_diffuse)}, {"minnaert_power", {0}}};
  for (double theta : {0.0, 30.0, 60.0, 89.0}) {
    expect_colour_near(eval("minnaert", lambertian, direction(theta), direction(45, 90)),
                       eval("lambert", {{"diffuse", to_param(rough_diffuse)}}, direction(theta), direction(45, 90)));
  }
}

TEST(Minnaert, DotsOfDifferentSignGiveZeroNotNaN) {
  // E10: pow(negative * positive, 0.8) is NaN; each dot is clamped first.
  expect_colour_near(eval("minnaert", minnaert, direction(60), direction(100)), glm::dvec3(0.0));
  expect_colour_near(eval("minnaert", minnaert, direction(100), direction(60)), glm::dvec3(0.0));
  // Both negative: the product is positive, but sat(N·L) = 0 and the clamps give 0 anyway.
  expect_colour_near(eval("minnaert", minnaert, direction(120), direction(100)), glm::dvec3(0.0));
}

// ---- oren_nayar: D sat(N·L) (A + B cosC sin(alpha) tan(beta)) (E8, E9) -----------------

const Params oren_nayar{{"diffuse", to_param(rough_diffuse)}, {"roughness_sq", {0.5}}};
// sigma² = 0.5: A = 1 - 0.5 * 0.5 / 0.83, B = 0.45 * 0.5 / 0.59 (the digest: 0.69880, 0.38136).
const double A = 1 - 0.25 / 0.83;
const double B = 0.225 / 0.59;

TEST(OrenNayar, CoefficientsAreTheBooks) {
  EXPECT_NEAR(A, 0.69880, 1e-5);
  EXPECT_NEAR(B, 0.38136, 1e-5);
}

TEST(OrenNayar, ZeroRoughnessIsLambert) {
  const Params smooth{{"diffuse", to_param(rough_diffuse)}, {"roughness_sq", {0}}};
  for (double theta_l : {0.0, 20.0, 50.0, 80.0, 100.0}) {
    for (double theta_v : {0.0, 30.0, 60.0, 89.0}) {
      for (double phi : {0.0, 45.0, 180.0}) {
        expect_colour_near(eval("oren_nayar", smooth, direction(theta_l, 0), direction(theta_v, phi)),
                           std::max(0.0, std::cos(glm::radians(theta_l))) * rough_diffuse, 1e-15);
      }
    }
  }
}

TEST(OrenNayar, LightAndEyeAlongTheNormalIsA) {
  // Both projections are zero vectors: cosC = 0 (E8), and beta = 0 anyway.
  expect_colour_near(eval("oren_nayar", oren_nayar, z_axis, z_axis), A * rough_diffuse);
}

TEST(OrenNayar, EitherDirectionAlongTheNormalLeavesOnlyA) {
  // E8: one projection is zero, cosC = 0 (and beta = 0: tan(beta) = 0).
  expect_colour_near(eval("oren_nayar", oren_nayar, z_axis, direction(60)), A * rough_diffuse);
  expect_colour_near(eval("oren_nayar", oren_nayar, direction(60), z_axis), 0.5 * A * rough_diffuse);
}

TEST(OrenNayar, ProjectionsShorterThanTheThresholdCountAsZero) {
  // E8's threshold, observable: V 1e-7 rad from N has a projection of squared length
  // 1e-14 < 1e-12, so cosC = 0 although the projection has a direction (normalised, it
  // would give cosC = 1 and add B sin60 tan(1e-7) = 3.3e-8). At 1e-5 rad (1e-10 > 1e-12)
  // the projection counts (to 1e-12: acos near 1 loses about ulp / sin(beta) = 1e-11 of beta).
  const glm::dvec3 L = direction(60, 0);
  const glm::dvec3 just_below(std::sin(1e-7), 0, std::cos(1e-7)), just_above(std::sin(1e-5), 0, std::cos(1e-5));
  expect_colour_near(eval("oren_nayar", oren_nayar, L, just_below), 0.5 * A * rough_diffuse, 1e-15);
  expect_colour_near(eval("oren_nayar", oren_nayar, L, just_above),
                     0.5 * (A + B * std::sin(glm::radians(60.0)) * std::tan(1e-5)) * rough_diffuse, 1e-12);
}

TEST(OrenNayar, RetroReflectionWithTheEyeAtTheLight) {
  // V = L at 60 degrees: alpha = beta = 60, cosC = 1, sin60 tan60 = 3/2.
  expect_colour_near(eval("oren_nayar", oren_nayar, direction(60, 30), direction(60, 30)),
                     0.5 * (A + 1.5 * B) * rough_diffuse);
}

TEST(OrenNayar, AlphaIsTheLargerAngleBetaTheSmaller) {
  // Same azimuth, L at 60 and V at 30 degrees: sin60 tan30 = 1/2; swapped, the same
  // product but N·L = cos 30.
  expect_colour_near(eval("oren_nayar", oren_nayar, direction(60, 0), direction(30, 0)), 0.5 * (A + 0.5 * B) * rough_diffuse);
  expect_colour_near(eval("oren_nayar", oren_nayar, direction(30, 0), direction(60, 0)),
                     cos30deg * (A + 0.5 * B) * rough_diffuse);
}

TEST(OrenNayar, AzimuthTermIsTheClampedCosineBetweenProjections) {
  // L and V at 60 degrees: sin(alpha) tan(beta) = 3/2; cosC = cos(azimuth difference).
  expect_colour_near(eval("oren_nayar", oren_nayar, direction(60, 0), direction(60, 60)),
                     0.5 * (A + B * 0.5 * 1.5) * rough_diffuse);
  expect_colour_near(eval("oren_nayar", oren_nayar, direction(60, 0), direction(60, 90)), 0.5 * A * rough_diffuse);
  expect_colour_near(eval("oren_nayar", oren_nayar, direction(60, 0), direction(60, 180)), 0.5 * A * rough_diffuse);
}

TEST(OrenNayar, LightBelowTheHorizonIsBlack) {
  expect_colour_near(eval("oren_nayar", oren_nayar, direction(100), direction(100)), glm::dvec3(0.0));
  // At the horizon exactly (N·L = 0, beta = acos(0), tan(beta) = 1.6e16 in double): 0, not
  // NaN. (Just above it, sat(N·L) tan(beta) tends to sin(beta): the colour is continuous
  // toward a non-zero limit when both L and V graze, and drops to 0 below the horizon.)
  expect_colour_near(eval("oren_nayar", oren_nayar, x_axis, x_axis), glm::dvec3(0.0));
}

TEST(OrenNayar, DotJustAboveOneIsClampedNotNaN) {
  // E9: a normal one ulp long makes N·L = 1 + 2^-52; acos of it is NaN unless clamped.
  // The model is given the normal as is (make_model, not evaluate(), which normalises).
  Shader shader("oren_nayar", oren_nayar);
  const glm::dvec3 long_normal(0, 0, one_plus_ulp());
  ASSERT_GT(glm::dot(long_normal, z_axis), 1.0);
  const glm::dvec3 colour = shader(z_axis, direction(30, 0), long_normal);
  // beta = acos(1) = 0, the L projection is ~1e-16 long: cosC = 0 (E8). D (N·L) A.
  expect_colour_near(colour, one_plus_ulp() * A * rough_diffuse, 1e-15);
}

TEST(OrenNayar, NegativeRoughnessIsAnError) {
  const auto negative = make_model("oren_nayar", {{"diffuse", grey(1)}, {"roughness_sq", {-0.1}}});
  ASSERT_FALSE(negative);
  EXPECT_EQ(negative.error(), "oren_nayar: parameter 'roughness_sq' must be >= 0 (it is sigma squared)");
}

}  // namespace
}  // namespace reference
