// point_attenuated, spot and warn (docs/models.md, errata E1, E11): first in the case
// scene's geometry (a point light at (0, 50, 0) whose light_vector (0, 1, 0) makes the
// spot shine straight down, a floor point at (x, 0, 0) with N = +y), then through
// evaluate()'s conventions (light at distance * L, spot axis -N by default).
#include <gtest/gtest.h>

#include <cmath>

#include "ModelTestSupport.h"

namespace reference {
namespace {

using namespace testing;

const glm::dvec3 y_up{0, 1, 0};
const glm::dvec3 floor_diffuse{0.9, 0.7, 0.5};
const glm::dvec3 light_color{1.0, 0.8, 2.0};
const ObjectSpaceLighting scene_lights{y_up, {0, 50, 0}, {-100, 50, 0}};

// The floor point (x, 0, 0) with normal N, lit by the scene's lights.
glm::dvec3 shade_floor(const Shader& shader, double x, const glm::dvec3& normal = y_up) {
  return shader.shade({{x, 0, 0}, normal, x_axis, {0, 0}}, scene_lights);
}

// ---- point_attenuated: D I sat(N·Lp) / (A d² + B d + C) ---------------------------------

const Params point_params{{"diffuse", to_param(floor_diffuse)}, {"light_color", to_param(light_color)}};

TEST(PointAttenuated, InverseFalloffOfTheDefaults) {
  Shader shader("point_attenuated", point_params);  // attenuation (0, 0.04, 0)
  // Straight below at d = 50: 1 / (0.04 * 50) = 1/2.
  expect_colour_near(shade_floor(shader, 0), 0.5 * floor_diffuse * light_color);
  // At (0, 25, 0) d = 25: the attenuation is exactly 1.
  expect_colour_near(shader.shade({{0, 25, 0}, y_up, x_axis, {0, 0}}, scene_lights), floor_diffuse * light_color);
  // (37.5, 0, 0): d = 62.5, N·Lp = 50/62.5 = 0.8, 0.8 / 2.5 = 0.32.
  expect_colour_near(shade_floor(shader, 37.5), 0.32 * floor_diffuse * light_color);
}

TEST(PointAttenuated, QuadraticLinearAndConstantTerms) {
  Params params = point_params;
  params["attenuation"] = {0.001, 0.01, 0.5};
  Shader shader("point_attenuated", params);
  // d = 50: 0.001 * 2500 + 0.01 * 50 + 0.5 = 3.5.
  expect_colour_near(shade_floor(shader, 0), floor_diffuse * light_color / 3.5);
}

TEST(PointAttenuated, UsesThePointLightNotTheDirectionalOne) {
  Shader shader("point_attenuated", point_params);
  ObjectSpaceLighting sideways = scene_lights;
  sideways.light_direction = x_axis;
  expect_colour_near(shader.shade({{0, 0, 0}, y_up, x_axis, {0, 0}}, sideways), 0.5 * floor_diffuse * light_color);
}

TEST(PointAttenuated, FacingAwayIsBlack) {
  Shader shader("point_attenuated", point_params);
  expect_colour_near(shade_floor(shader, 0, -y_up), glm::dvec3(0.0));
  expect_colour_near(shade_floor(shader, 10, x_axis), glm::dvec3(0.0));  // Lp·x < 0
}

TEST(PointAttenuated, AttenuationNeedsThreeValues) {
  Params params = point_params;
  params["attenuation"] = {0, 0.04, 0, 1};
  const auto error = make_model("point_attenuated", params);
  ASSERT_FALSE(error);
  EXPECT_EQ(error.error(), "point_attenuated: parameter 'attenuation' needs 3 values, got 4 value(s)");
}

// ---- spot: point_attenuated times s(cos(theta)), cos(theta) = Lp·L (E1) ------------------

const double cos_umbra = 0.9659, cos_penumbra = 0.8660;
const Params spot_params{{"diffuse", to_param(floor_diffuse)}, {"light_color", to_param(light_color)}};

// The floor x at which the light sees the point at cos(theta) = c (it is 50 below).
double floor_x_at(double cos_theta) { return 50 * std::tan(std::acos(cos_theta)); }

TEST(Spot, InsideTheUmbraEqualsThePointLight) {
  Shader spot("spot", spot_params), point("point_attenuated", point_params);
  for (double x : {0.0, 5.0, 10.0, floor_x_at(cos_umbra) - 0.01}) {
    expect_colour_near(shade_floor(spot, x), shade_floor(point, x));
    EXPECT_GT(shade_floor(spot, x).r, 0.0);
  }
}

TEST(Spot, OutsideThePenumbraIsBlack) {
  Shader spot("spot", spot_params);
  for (double x : {floor_x_at(cos_penumbra) + 0.01, 40.0, 100.0}) {
    expect_colour_near(shade_floor(spot, x), glm::dvec3(0.0));
  }
}

TEST(Spot, PenumbraFallsFromOneAtTheUmbraToZeroAtItsEdge) {
  // E1: ((cos(theta) - cos_penumbra) / (cos_umbra - cos_penumbra))^falloff; the book's
  // printed form runs the other way (0 at the umbra, 1 at the penumbra edge).
  Shader spot("spot", spot_params), point("point_attenuated", point_params);
  const double middle = 0.5 * (cos_umbra + cos_penumbra);
  const double x = floor_x_at(middle);
  expect_colour_near(shade_floor(spot, x), 0.5 * shade_floor(point, x), 1e-12);
  // Continuous at both edges.
  EXPECT_NEAR(shade_floor(spot, floor_x_at(cos_umbra - 1e-9)).r, shade_floor(point, floor_x_at(cos_umbra)).r, 1e-6);
  EXPECT_NEAR(shade_floor(spot, floor_x_at(cos_penumbra + 1e-9)).r, 0.0, 1e-6);
  // Monotonic across the penumbra.
  double previous = INFINITY;
  for (double t = 0.01; t < 1; t += 0.01) {
    const double x_t = floor_x_at(cos_umbra + t * (cos_penumbra - cos_umbra));
    const double s = shade_floor(spot, x_t).r / shade_floor(point, x_t).r;
    EXPECT_LT(s, previous) << t;
    EXPECT_NEAR(s, 1 - t, 1e-9) << t;  // falloff 1: linear in cos(theta)
    previous = s;
  }
}

TEST(Spot, FalloffIsAnExponent) {
  Params squared = spot_params;
  squared["falloff"] = {2};
  Shader spot("spot", squared), point("point_attenuated", point_params);
  const double x = floor_x_at(0.5 * (cos_umbra + cos_penumbra));
  expect_colour_near(shade_floor(spot, x), 0.25 * shade_floor(point, x), 1e-12);
}

TEST(Spot, EqualConesAreAHardEdgeWithoutDividingByZero) {
  Params hard = spot_params;
  hard["cos_umbra"] = {0.9};
  hard["cos_penumbra"] = {0.9};
  Shader spot("spot", hard), point("point_attenuated", point_params);
  expect_colour_near(shade_floor(spot, floor_x_at(0.9) - 0.01), shade_floor(point, floor_x_at(0.9) - 0.01));
  expect_colour_near(shade_floor(spot, floor_x_at(0.9) + 0.01), glm::dvec3(0.0));
}

TEST(Spot, ThroughEvaluateTheAxisIsMinusTheNormal) {
  // Default axis -N: cos(theta) = N·L. L = N: on the axis, the point light at d = 50.
  const glm::dvec3 on_axis = eval("spot", spot_params, z_axis, z_axis);
  expect_colour_near(on_axis, 0.5 * floor_diffuse * light_color);
  // L at 20 degrees: cos 20 = 0.9397, in the penumbra.
  const double c20 = std::cos(glm::radians(20.0));
  const double s = (c20 - cos_penumbra) / (cos_umbra - cos_penumbra);
  expect_colour_near(eval("spot", spot_params, direction(20), z_axis), s * c20 * 0.5 * floor_diffuse * light_color);
  // L at 40 degrees: outside.
  expect_colour_near(eval("spot", spot_params, direction(40), z_axis), glm::dvec3(0.0));
  // An axis pointing from the light at the point: always in the umbra.
  Configuration aimed{direction(40), z_axis, z_axis, x_axis, 50, -direction(40)};
  expect_colour_near(eval("spot", spot_params, aimed), eval("point_attenuated", point_params, direction(40), z_axis));
}

// ---- warn: D I / d² sat(Lp·L)^alpha sat(N·Lp) (E11) --------------------------------------

const Params warn_params{{"diffuse", to_param(floor_diffuse)}, {"light_color", {1000, 1000, 1000}}, {"warn_exponent", {10}}};

TEST(Warn, OnTheAxisIsInverseSquareTimesLambert) {
  Shader warn("warn", warn_params);
  // Straight below at d = 50: 1000 / 2500 = 0.4, both cosines 1.
  expect_colour_near(shade_floor(warn, 0), 0.4 * floor_diffuse);
  // A normal tilted 60 degrees from +y, on the axis: only the Lambert factor changes.
  const glm::dvec3 normal(std::sin(glm::radians(60.0)), std::cos(glm::radians(60.0)), 0);
  expect_colour_near(shade_floor(warn, 0, normal), 0.4 * 0.5 * floor_diffuse);
}

TEST(Warn, OffTheAxisTheConeIsCosineToTheExponent) {
  Shader warn("warn", warn_params);
  // (20, 0, 0): d² = 2900, cos(theta) = 50 / sqrt(2900) = N·Lp.
  const double cos_theta = 50 / std::sqrt(2900.0);
  expect_colour_near(shade_floor(warn, 20), 1000 / 2900.0 * std::pow(cos_theta, 11) * floor_diffuse, 1e-14);
}

TEST(Warn, BehindTheLightAndFacingAwayAreZeroNotNaN) {
  // E11: Lp·L < 0 (a point above the light) would make pow(negative, alpha) NaN for a
  // non-integer alpha; N·Lp < 0 would give a negative colour.
  Params fractional = warn_params;
  fractional["warn_exponent"] = {10.5};
  Shader warn("warn", fractional);
  const glm::dvec3 above = warn.shade({{10, 60, 0}, -y_up, x_axis, {0, 0}}, scene_lights);
  expect_colour_near(above, glm::dvec3(0.0));
  expect_colour_near(shade_floor(warn, 0, -y_up), glm::dvec3(0.0));
}

TEST(Warn, ThroughEvaluateTheConeFollowsTheAngleOfIncidence) {
  // Default axis -N: cos(theta) = N·L = N·Lp, so colour = I/d² cos^(alpha + 1).
  expect_colour_near(eval("warn", warn_params, z_axis, direction(70)), 0.4 * floor_diffuse);
  const double c = std::cos(glm::radians(25.0));
  expect_colour_near(eval("warn", warn_params, direction(25, 40), z_axis), 0.4 * std::pow(c, 11) * floor_diffuse, 1e-14);
  // Distance: inverse square.
  expect_colour_near(eval("warn", warn_params, z_axis, z_axis, z_axis, x_axis, 100), 0.1 * floor_diffuse);
}

}  // namespace
}  // namespace reference
