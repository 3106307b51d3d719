// Cook-Torrance (docs/models.md, errata E6, E9) at hand-computed configurations in the
// local frame of evaluate() (N = +z): diffuse F D G / ((N·L)(N·V)) for N·L, N·V > 0.
#include <gtest/gtest.h>

#include <cmath>

#include "ModelTestSupport.h"

namespace reference {
namespace {

using namespace testing;

const glm::dvec3 scale{0.8, 0.6, 0.4};  // `diffuse`, the overall scale
const double c = 0.5, m = 0.5, r0 = 0.5;
const Params params{{"diffuse", to_param(scale)}, {"gaussian_c", {c}}, {"slope_m", {m}}, {"fresnel_r0", {r0}}};

double cos_deg(double degrees) { return std::cos(glm::radians(degrees)); }
double blinn_d(double alpha_degrees) { return c * std::exp(-std::pow(glm::radians(alpha_degrees) / m, 2)); }
double schlick_f(double v_dot_h) { return r0 + (1 - r0) * std::pow(1 - v_dot_h, 5); }

TEST(CookTorrance, EverythingAlongTheNormalIsCTimesR0) {
  // H = N: D = c, G = min(1, 2, 2) = 1, F = r0 + (1 - r0) 0^5 = r0, (N·L)(N·V) = 1.
  expect_colour_near(eval("cook_torrance", params, z_axis, z_axis), c * r0 * scale);
  EXPECT_NEAR(eval("cook_torrance", {}, z_axis, z_axis).r, 0.25, 1e-15);  // the defaults
}

TEST(CookTorrance, MirrorDirection) {
  // L, V at 60 degrees on opposite sides: H = N, D = c, V·H = cos 60 = 1/2,
  // G = min(1, 2 * 1/2 / (1/2), ...) = 1, F = r0 + (1 - r0) / 32, divided by 1/4.
  expect_colour_near(eval("cook_torrance", params, direction(60, 0), direction(60, 180)),
                     schlick_f(0.5) * c / 0.25 * scale);
}

TEST(CookTorrance, ShadowingWithTheEyeAlongTheNormal) {
  // L at 80 degrees, V = N: H at 40 degrees, N·H = V·H = cos 40, so
  // G = min(1, 2, 2 N·L) = 2 cos 80 and F D G / ((N·L)(N·V)) = 2 F D.
  const double expected = 2 * schlick_f(cos_deg(40)) * blinn_d(40);
  expect_colour_near(eval("cook_torrance", params, direction(80), z_axis), expected * scale);
}

TEST(CookTorrance, GeometryAndFresnelUseVDotH) {
  // E6. L at 80 degrees, V at 20 degrees on the other side: H at 30 degrees from N, half
  // angle 50 degrees: N·H = cos30, V·H = cos50, N·L = cos80, N·V = cos20.
  // G = min(1, 2 cos30 cos20 / cos50, 2 cos30 cos80 / cos50) = 0.4679 (the book's shader,
  // dividing by N·H, would give 2 cos80 = 0.3473); F in V·H, not the shader's N·L.
  const double g = 2 * cos_deg(30) * cos_deg(80) / cos_deg(50);
  EXPECT_LT(g, 1.0);
  EXPECT_LT(g, 2 * cos_deg(30) * cos_deg(20) / cos_deg(50));
  const double expected = schlick_f(cos_deg(50)) * blinn_d(30) * g / (cos_deg(80) * cos_deg(20));
  expect_colour_near(eval("cook_torrance", params, direction(80, 0), direction(20, 180)), expected * scale);
  // Reciprocal in L and V (the radiance-level function; see brdf_properties_test.cpp).
  expect_colour_near(eval("cook_torrance", params, direction(20, 180), direction(80, 0)), expected * scale);
}

TEST(CookTorrance, ZeroUnlessLightAndEyeAreAboveTheSurface) {
  // E6: the unguarded division by (N·L)(N·V) is gated instead.
  expect_colour_near(eval("cook_torrance", params, direction(30), direction(95)), glm::dvec3(0.0));
  expect_colour_near(eval("cook_torrance", params, direction(95), direction(30)), glm::dvec3(0.0));
  expect_colour_near(eval("cook_torrance", params, x_axis, direction(30, 180)), glm::dvec3(0.0));  // N·L = 0 exactly
  expect_colour_near(eval("cook_torrance", params, direction(120, 0), direction(120, 180)), glm::dvec3(0.0));
}

TEST(CookTorrance, DotJustAboveOneIsClampedNotNaN) {
  // E9: with a normal one ulp long, N·H = 1 + 2^-52 and acos would be NaN unclamped.
  // (sat() only clamps below.) Given to the model as is, not through evaluate().
  Shader shader("cook_torrance", params);
  const glm::dvec3 long_normal(0, 0, one_plus_ulp());
  const glm::dvec3 colour = shader(z_axis, z_axis, long_normal);
  expect_colour_near(colour, c * r0 * scale, 1e-14);
}

TEST(CookTorrance, RougherSlopeWidensTheLobe) {
  // D = c exp(-(a/m)²): at a = 30 degrees, m = 1 keeps far more than m = 0.5.
  Params rough = params;
  rough["slope_m"] = {1.0};
  const double narrow = eval("cook_torrance", params, direction(60), z_axis).r;
  const double wide = eval("cook_torrance", rough, direction(60), z_axis).r;
  EXPECT_NEAR(wide / narrow, std::exp(-std::pow(glm::radians(30.0), 2) * (1 - 4)), 1e-12);
}

TEST(CookTorrance, SlopeMustBePositive) {
  Params zero = params;
  zero["slope_m"] = {0};
  const auto error = make_model("cook_torrance", zero);
  ASSERT_FALSE(error);
  EXPECT_EQ(error.error(), "cook_torrance: parameter 'slope_m' must be > 0 (m divides the facet angle)");
}

}  // namespace
}  // namespace reference
