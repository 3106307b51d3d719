// Blinn-Phong and Schlick (docs/models.md) at hand-computed configurations, in the local
// frame of evaluate(): N = +z, directions by polar angle from N (and azimuth).
#include <gtest/gtest.h>

#include <cmath>

#include "ModelTestSupport.h"

namespace reference {
namespace {

using namespace testing;

const glm::dvec3 coloured_diffuse{0.2, 0.3, 0.4};
const glm::dvec3 coloured_specular{0.5, 0.6, 0.7};
const Params coloured{{"diffuse", to_param(coloured_diffuse)}, {"specular", to_param(coloured_specular)}, {"power", {7}}};

// ---- blinn_phong: D sat(N·L) + S sat(N·H)^power, not gated by N·L (E7) ----------------

TEST(BlinnPhong, LightAndEyeAlongTheNormalIsDiffusePlusSpecular) {
  expect_colour_near(eval("blinn_phong", coloured, z_axis, z_axis), coloured_diffuse + coloured_specular);
}

TEST(BlinnPhong, AtTheMirrorDirectionHIsNAndTheHighlightIsFull) {
  // L at 60 degrees, V at 60 degrees on the other side: H = N, so D cos(60) + S.
  expect_colour_near(eval("blinn_phong", coloured, direction(60, 0), direction(60, 180)), 0.5 * coloured_diffuse + coloured_specular);
}

TEST(BlinnPhong, HalfwayBetweenLightAndNormal) {
  // L at 60 degrees, V = N: H at 30 degrees, N·H = cos 30 = sqrt(3)/2.
  const double highlight = std::pow(std::sqrt(3.0) / 2, 7);
  expect_colour_near(eval("blinn_phong", coloured, direction(60), z_axis), 0.5 * coloured_diffuse + highlight * coloured_specular);
  // Phong at the same configuration: R·V = cos 60, a different (smaller) highlight.
  expect_colour_near(eval("phong", coloured, direction(60), z_axis), 0.5 * coloured_diffuse + std::pow(0.5, 7) * coloured_specular);
}

TEST(BlinnPhong, PowerSharpensTheHighlight) {
  const Params sharp{{"diffuse", grey(0)}, {"specular", grey(1)}, {"power", {50}}};
  EXPECT_NEAR(eval("blinn_phong", sharp, direction(60), z_axis).r, std::pow(std::cos(glm::radians(30.0)), 50), 1e-15);
}

TEST(BlinnPhong, SpecularIsNotGatedByTheDiffuseTerm) {
  // E7. L at 120 degrees (below the horizon, no diffuse) and V at 30 degrees on the other
  // side: L + V = (sin120 - sin30, 0, cos120 + cos30) = (0.366, 0, 0.366), H at 45 degrees.
  const glm::dvec3 colour = eval("blinn_phong", coloured, direction(120, 0), direction(30, 180));
  expect_colour_near(colour, std::pow(std::sqrt(0.5), 7) * coloured_specular);
}

TEST(BlinnPhong, HalfVectorBelowTheSurfaceGivesNoHighlight) {
  // L and V both at 120 degrees, opposite azimuths: H = -N, sat(N·H) = 0.
  expect_colour_near(eval("blinn_phong", coloured, direction(120, 0), direction(120, 180)), glm::dvec3(0.0));
}

TEST(BlinnPhong, OppositeLightAndEyeHaveNoHalfVectorAndNoHighlight) {
  // L = -V exactly: H = normalize(0) is undefined (docs/errata.md); the reference takes
  // N·H = 0, so only the diffuse term remains, and nothing is NaN.
  expect_colour_near(eval("blinn_phong", coloured, direction(30, 0), -direction(30, 0)),
                     std::cos(glm::radians(30.0)) * coloured_diffuse);
  expect_colour_near(eval("blinn_phong", coloured, x_axis, -x_axis), glm::dvec3(0.0));
}

TEST(BlinnPhong, AShortButNonZeroSumStillDefinesTheHalfVector) {
  // L and V 1e-9 rad above the horizon on opposite sides: |L + V| = 2e-9, H = N exactly,
  // so the highlight is the whole specular colour (it used to be 0 below |L + V|² = 1e-12).
  const glm::dvec3 L(1, 0, 1e-9), V(-1, 0, 1e-9);
  expect_colour_near(eval("blinn_phong", coloured, L, V), 1e-9 * coloured_diffuse + coloured_specular);
  // A sum 1.4e-9 long along (0, 1, 1): H at 45 degrees from N.
  expect_colour_near(eval("blinn_phong", coloured, glm::dvec3(1, 1e-9, 1e-9), glm::dvec3(-1, 0, 0)),
                     1e-9 * coloured_diffuse + std::pow(std::sqrt(0.5), 7) * coloured_specular);
}

// ---- schlick: D sat(N·L) + S t/(n - (n - 1) t), t = sat(R·V) -----------------------------

TEST(Schlick, AtTheMirrorDirectionTheHighlightIsTheSpecularColour) {
  // R·V = 1: 1/(n - (n - 1)) = 1.
  expect_colour_near(eval("schlick", coloured, direction(60, 0), direction(60, 180)), 0.5 * coloured_diffuse + coloured_specular);
  expect_colour_near(eval("schlick", coloured, z_axis, z_axis), coloured_diffuse + coloured_specular);
}

TEST(Schlick, RationalFunctionAtHalf) {
  // L at 60 degrees, V = N: R·V = cos 60 = 1/2, t/(7 - 6t) = 0.5/4 = 1/8.
  expect_colour_near(eval("schlick", coloured, direction(60), z_axis), 0.5 * coloured_diffuse + 0.125 * coloured_specular);
  // n = 1: the term is t itself.
  Params linear = coloured;
  linear["power"] = {1};
  expect_colour_near(eval("schlick", linear, direction(60), z_axis), 0.5 * coloured_diffuse + 0.5 * coloured_specular);
}

TEST(Schlick, IsCloseToPhongNearTheMirrorDirectionButCheaper) {
  // Not an identity, a sanity bound: at R·V = cos 10 degrees (L at 60, V at 50 degrees
  // on the other side) Schlick's t/(7 - 6t) = 0.9025 against Phong's t^7 = 0.8983.
  const double t = std::cos(glm::radians(10.0));
  const Params white{{"diffuse", grey(0)}, {"specular", grey(1)}, {"power", {7}}};
  const double schlick = eval("schlick", white, direction(60, 0), direction(50, 180)).r;
  EXPECT_NEAR(schlick, t / (7 - 6 * t), 1e-14);
  EXPECT_NEAR(schlick, std::pow(t, 7), 0.1);
}

TEST(Schlick, NoHighlightWhenReflectionPointsAwayFromTheEye) {
  // V = L at 60 degrees: R·V = cos 120 < 0, t = 0.
  expect_colour_near(eval("schlick", coloured, direction(60), direction(60)), 0.5 * coloured_diffuse);
}

TEST(Schlick, SpecularIsNotGatedByTheDiffuseTerm) {
  // E7: L at 120 degrees; the eye along R (also below the horizon) sees the full highlight.
  const glm::dvec3 to_light = direction(120);
  const glm::dvec3 reflection = 2.0 * z_axis * glm::dot(z_axis, to_light) - to_light;
  expect_colour_near(eval("schlick", coloured, to_light, reflection), coloured_specular);
  expect_colour_near(eval("phong", coloured, to_light, reflection), coloured_specular);
}

TEST(Schlick, PowerMustBePositive) {
  const auto zero = make_model("schlick", {{"diffuse", grey(1)}, {"specular", grey(1)}, {"power", {0}}});
  ASSERT_FALSE(zero);
  EXPECT_EQ(zero.error(), "schlick: parameter 'power' must be > 0 (the denominator n - (n-1) t vanishes otherwise)");
  EXPECT_TRUE(make_model("schlick", {{"diffuse", grey(1)}, {"specular", grey(1)}, {"power", {0.5}}}));
}

}  // namespace
}  // namespace reference
