// The faults found at the extremes, each as a plain example (oracle_test.cpp
// sweeps them against the 50-digit oracle): vectors whose squared length under- or
// overflows, point lights very near and very far, a short tangent, a sharp lobe's peak.
#include <gtest/gtest.h>

#include <cmath>

#include "ModelTestSupport.h"

namespace reference {
namespace {

using namespace testing;

TEST(Extremes, EvaluateNormalisesVectorsOfAnyFiniteLength) {
  const glm::dvec3 L = direction(40, 10), V = direction(30, 200), N = direction(5, 90), T = direction(90, 30);
  for (const std::string& name : model_names()) {
    const glm::dvec3 unit = eval(name, {}, L, V, N, T);
    for (const double scale : {1e-200, 1e-300, 1e200, 1e300}) {
      const glm::dvec3 scaled = eval(name, {}, L * scale, V * scale, N * scale, T * scale);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(scaled[i], unit[i], 1e-14 * std::abs(unit[i])) << name << " " << scale;
    }
  }
}

TEST(Extremes, PointLightsVeryNearAndVeryFar) {
  // point_attenuated with (0, 0.04, 0): cos(theta) / (0.04 d); warn: 1000 cos^10 cos / d²
  // with the axis along -L (so the cone factor is 1).
  const glm::dvec3 L = direction(60);
  for (const double d : {1e-200, 1e-160, 1e-100, 1e100, 1e160, 1e200}) {
    const double expected = 0.5 / (0.04 * d);
    EXPECT_NEAR(eval("point_attenuated", {}, L, z_axis, z_axis, x_axis, d).r, expected, 1e-15 * expected) << d;
    const double warn = 1000 * 0.5 / d / d;
    const Configuration on_axis{L, z_axis, z_axis, x_axis, d, -L};
    if (std::isfinite(warn) && warn > 1e-290) {  // not subnormal
      EXPECT_NEAR(eval("warn", {}, on_axis).r, warn, 1e-15 * warn) << d;
    }
  }
  // A quadratic falloff too far for d² still gives the (tiny, finite) colour.
  const double far = eval("point_attenuated", {{"attenuation", {1e-3, 0, 0}}}, L, z_axis, z_axis, x_axis, 1e155).r;
  EXPECT_NEAR(far, 0.5 / 1e-3 / 1e155 / 1e155, 1e-14 * far);
}

TEST(Extremes, WardAnisotropicFrameFromAShortOrNearlyParallelTangent) {
  const Params sharp{{"roughness_xy", {0.3, 0.05}}};
  const glm::dvec3 L = direction(40, 10), V = direction(35, 200);
  const glm::dvec3 T = direction(90, 30);
  const glm::dvec3 reference_colour = eval("ward_aniso", sharp, L, V, z_axis, T);
  EXPECT_GT(reference_colour.r, eval("lambert", {}, L, V).r) << "a specular term";
  for (const double length : {1e-7, 1e-100, 1e-300, 1e200})
    expect_colour_near(Shader("ward_aniso", sharp)(L, V, z_axis, T * length), reference_colour, 1e-13);
  // T 1e-9 rad off the normal, in the plane of the same azimuth: the same frame.
  expect_colour_near(Shader("ward_aniso", sharp)(L, V, z_axis, z_axis + 1e-9 * T), reference_colour, 1e-13);
}

TEST(Extremes, SharpLobePeakKeepsItsDigits) {
  // Ward isotropic, sigma = 1e-5, H 1e-5 rad from N (L and V at +-30 degrees about H in the
  // x-z plane): exp(-tan²(1e-5) / 1e-10) / (4 pi 1e-10) / cos30 · cos(30 + 1e-5). With
  // 1 - (N·H)², the exponent is off by ~1e-6 here.
  const double sigma = 1e-5, gamma = 1e-5, theta = glm::radians(30.0);
  const glm::dvec3 L(std::sin(gamma + theta), 0, std::cos(gamma + theta)),
      V(std::sin(gamma - theta), 0, std::cos(gamma - theta));
  const double t = std::tan(gamma) / sigma;
  const double spec = std::exp(-t * t) / (4 * pi * sigma * sigma) / std::sqrt(L.z * V.z);
  const double colour = eval("ward_iso", {{"roughness", {sigma}}, {"diffuse", {0, 0, 0}}}, L, V).r;
  // L and V's own rounding moves gamma by ~1e-16 rad: 2 gamma / sigma² · 1e-16 = 2e-11.
  EXPECT_NEAR(colour, spec * L.z, 1e-10 * colour);
}

}  // namespace
}  // namespace reference
