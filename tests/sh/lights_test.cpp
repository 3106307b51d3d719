// Lights (sh/Lights.h): D3DX's directional and cone lights against DirectXSH's formulas,
// the irradiance convolution, and the analytic sky.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sh/Basis.h"
#include "sh/Lights.h"
#include "sh/Projection.h"
#include "sh/Sampling.h"

namespace sh {
namespace {

using std::numbers::pi;

const glm::dvec3 light_direction = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
const glm::dvec3 colour{1.0, 0.5, 0.25};

std::vector<double> basis_at(int bands, const glm::dvec3& d) {
  std::vector<double> y(std::size_t(coefficient_count(bands)));
  basis_all(bands, d, y);
  return y;
}

// Exit radiance of an unshadowed albedo-1 diffuse point with normal n under SH light L:
// E(n) / pi with E the irradiance map.
glm::dvec3 exit_radiance(const std::vector<glm::dvec3>& light, const glm::dvec3& n) {
  return evaluate(irradiance_coefficients(light), n) / pi;
}

// ---- irradiance ------------------------------------------------------------------------------

TEST(Irradiance, WeightsAreTheClampedCosineConvolution) {
  const std::vector<double> a = band_limited_irradiance_weights(21);
  EXPECT_NEAR(a[0], pi, 1e-14);
  EXPECT_NEAR(a[1], 2 * pi / 3, 1e-14);
  EXPECT_NEAR(a[2], pi / 4, 1e-14);
  EXPECT_NEAR(a[3], 0.0, 1e-14);
  EXPECT_NEAR(a[4], -pi / 24, 1e-14);
  // Even l >= 2: 2 pi (-1)^(l/2-1) / ((l+2)(l-1)) * l! / (2^l ((l/2)!)^2); odd l >= 3: 0.
  double central = 0.5;  // C(l, l/2) / 2^l at l = 2
  for (int l = 2; l <= 20; l += 2) {
    const double expected = 2 * pi * ((l / 2) % 2 == 1 ? 1 : -1) / ((l + 2.0) * (l - 1.0)) * central;
    EXPECT_NEAR(a[l], expected, 1e-14) << l;
    central *= (l + 1.0) * (l + 2.0) / (4.0 * (l / 2 + 1.0) * (l / 2 + 1.0));
  }
  for (int l = 3; l <= 20; l += 2) EXPECT_NEAR(a[l], 0.0, 1e-14) << l;
}

TEST(Irradiance, DirectionalLightAtThreeBandsIsTheClosedFormClampedCosine) {
  // L = s y(d): E(n) = s sum_l A_l (2l+1)/(4 pi) P_l(n.d) = s (1/4 + t/2 + 5/16 P_2(t)).
  const DirectionalLight light = make_directional_light(light_direction, {1, 1, 1}).value();
  const std::vector<glm::dvec3> c = light.coefficients(3);
  const double s = pi / 1.0625;
  for (double angle = 0; angle <= pi; angle += pi / 12) {
    const glm::dvec3 side = glm::normalize(glm::cross(light_direction, {0, 0, 1}));
    const glm::dvec3 n = std::cos(angle) * light_direction + std::sin(angle) * side;
    const double t = glm::dot(n, light_direction);
    const double closed_form = s * (0.25 + 0.5 * t + 5.0 / 16 * (3 * t * t - 1) / 2);
    EXPECT_NEAR(evaluate(irradiance_coefficients(c), n).x, closed_form, 1e-13) << angle;
  }
}

TEST(Irradiance, ClampedCosineTransferGivesTheSameShading) {
  // Shading by transfer (8.2.4.2) equals the irradiance map: dot(L, max(0, n.w)) = E(n).
  const std::vector<glm::dvec3> light = make_cone_light(light_direction, 0.7, colour).value().coefficients(6);
  const glm::dvec3 n = glm::normalize(glm::dvec3(-0.2, 0.1, 1));
  const glm::dvec3 by_transfer = dot(light, std::span<const double>(clamped_cosine(6, n)));
  const glm::dvec3 by_map = evaluate(irradiance_coefficients(light), n);
  EXPECT_NEAR(glm::length(by_transfer - by_map), 0.0, 1e-13);
}

// ---- D3DX directional light ------------------------------------------------------------------

TEST(DirectionalLight, IsD3dxFormula) {
  // DirectXSH.cpp: result = y(dir) * pi / CosWtInt(order) * colour, with CosWtInt =
  // 0.25 + 0.5 (+ 5/16 for order > 2) (- 3/32 for order > 4).
  const double cos_wt_int[7] = {0, 0, 0.75, 1.0625, 1.0625, 0.96875, 0.96875};
  const DirectionalLight light = make_directional_light(2.0 * light_direction, colour).value();
  EXPECT_NEAR(glm::length(light.direction), 1.0, 1e-15);
  for (int order = 2; order <= 6; ++order) {
    EXPECT_NEAR(directional_light_normalisation(order), cos_wt_int[order], 1e-14) << order;
    const std::vector<glm::dvec3> c = light.coefficients(order);
    const std::vector<double> y = basis_at(order, light_direction);
    ASSERT_EQ(c.size(), y.size());
    for (std::size_t i = 0; i < y.size(); ++i)
      EXPECT_NEAR(glm::length(c[i] - y[i] * pi / cos_wt_int[order] * colour), 0.0, 1e-14) << order << " " << i;
  }
}

TEST(DirectionalLight, FacingPointReflectsTheColourInSHAndExactly) {
  const DirectionalLight light = make_directional_light(light_direction, colour).value();
  for (int bands = 1; bands <= 8; ++bands)
    EXPECT_NEAR(glm::length(exit_radiance(light.coefficients(bands), light_direction) - colour), 0.0, 1e-13) << bands;
  EXPECT_NEAR(glm::length(light.exit_radiance(light_direction) - colour), 0.0, 1e-15);
  EXPECT_EQ(light.irradiance(), pi * colour);
  EXPECT_EQ(light.exit_radiance(-light_direction), glm::dvec3(0.0));
}

TEST(DirectionalLight, RejectsBadInput) {
  EXPECT_FALSE(make_directional_light({0, 0, 0}, colour).has_value());
  EXPECT_FALSE(make_directional_light({NAN, 0, 1}, colour).has_value());
  EXPECT_FALSE(make_directional_light({0, 0, 1}, {INFINITY, 0, 0}).has_value());
}

// ---- D3DX cone light -------------------------------------------------------------------------

// DirectXSH's ComputeCapInt: the integral of y_l0 over a cap of half-angle a about +z,
// here from integral_c^1 P_l = (P_{l-1}(c) - P_{l+1}(c)) / (2l+1) (c = cos a), and the
// coefficient sqrt(4 pi/(2l+1)) cap_l y_lm(d) / sin^2(min(a, pi/2)) * colour.
double cap_integral(int l, double a) {
  const double c = std::cos(a);
  auto p = [](int n, double x) { return n < 0 ? 1.0 : legendre(n, 0, x); };
  const double integral = l == 0 ? 1 - c : (p(l - 1, c) - p(l + 1, c)) / (2 * l + 1);
  return 2 * pi * normalisation(l, 0) * integral;
}

TEST(ConeLight, IsD3dxFormula) {
  for (double radius : {0.05, 0.3, 1.0, pi / 2, 2.0, pi}) {
    const ConeLight light = make_cone_light(light_direction, radius, colour).value();
    const double s = std::sin(std::min(radius, pi / 2));
    const std::vector<glm::dvec3> c = light.coefficients(6);
    const std::vector<double> y = basis_at(6, light_direction);
    for (int l = 0; l < 6; ++l)
      for (int m = -l; m <= l; ++m) {
        const glm::dvec3 expected =
            std::sqrt(4 * pi / (2 * l + 1)) * cap_integral(l, radius) * y[index(l, m)] / (s * s) * colour;
        EXPECT_NEAR(glm::length(c[index(l, m)] - expected), 0.0, 1e-13) << radius << " " << l << " " << m;
      }
  }
  // DirectXSH's literal l = 1 cap: sqrt(3) sqrt(pi) sin^2(a) / 2.
  EXPECT_NEAR(cap_integral(1, 0.4), std::sqrt(3 * pi) * std::pow(std::sin(0.4), 2) / 2, 1e-15);
}

TEST(ConeLight, ExactLightFacingPointReflectsTheColour) {
  for (double radius : {0.2, 1.0, 2.5}) {
    const ConeLight light = make_cone_light(light_direction, radius, colour).value();
    // The cosine-weighted solid angle of the cap within the facing hemisphere: pi sin^2.
    const double s = std::sin(std::min(radius, pi / 2));
    EXPECT_NEAR(glm::length(light.radiance() * (s * s) - colour), 0.0, 1e-15);
    EXPECT_EQ(light(light_direction), light.radiance());
    EXPECT_EQ(light(-light_direction), radius < pi ? glm::dvec3(0.0) : light.radiance());
  }
}

TEST(ConeLight, CoefficientsAreTheProjectionOfTheExactRadiance) {
  // A stratified estimate of the exact light's projection; the cone's rim is the only
  // noise, about 1e-2 at 200 x 200 samples for this cone.
  const ConeLight light = make_cone_light(light_direction, 0.5, colour).value();
  const SampleSet set(jittered_samples(200, 3), 4);
  const std::vector<glm::dvec3> numeric = project_rgb([&](const glm::dvec3& w) { return light(w); }, set);
  const std::vector<glm::dvec3> c = light.coefficients(4);
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(numeric[i].x, c[i].x, 3e-2) << i;
}

TEST(ConeLight, SmallConeTendsToTheExactDelta) {
  // Radiance colour/sin^2(a) over a cap of pi a^2: a delta of strength pi colour, so
  // pi y(d) colour = CosWtInt(bands) x D3DX's directional light, with an O(a^2 l^2) error.
  const DirectionalLight directional = make_directional_light(light_direction, colour).value();
  for (int bands : {2, 3, 5}) {
    const std::vector<glm::dvec3> cone = make_cone_light(light_direction, 1e-3, colour).value().coefficients(bands);
    const std::vector<glm::dvec3> d3dx = directional.coefficients(bands);
    const std::vector<double> y = basis_at(bands, light_direction);
    for (std::size_t i = 0; i < y.size(); ++i) {
      EXPECT_NEAR(glm::length(cone[i] - pi * y[i] * colour), 0.0, 1e-5) << i;
      EXPECT_NEAR(glm::length(cone[i] - directional_light_normalisation(bands) * d3dx[i]), 0.0, 1e-5) << i;
    }
  }
  // Below 1e-4 the cone is D3DX's directional light, as in DirectXSH.
  const ConeLight tiny = make_cone_light(light_direction, 5e-5, colour).value();
  EXPECT_TRUE(tiny.is_directional());
  const std::vector<glm::dvec3> a = tiny.coefficients(4), b = directional.coefficients(4);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(a[i], b[i]);
}

TEST(ConeLight, RejectsBadInput) {
  EXPECT_FALSE(make_cone_light(light_direction, -0.1, colour).has_value());
  EXPECT_FALSE(make_cone_light(light_direction, 3.5, colour).has_value());
  EXPECT_FALSE(make_cone_light(light_direction, NAN, colour).has_value());
  EXPECT_FALSE(make_cone_light({0, 0, 0}, 0.5, colour).has_value());
  EXPECT_TRUE(make_cone_light(light_direction, pi, colour).has_value());
}

// ---- the analytic sky ------------------------------------------------------------------------

TEST(SkyLight, RadianceIsAsDocumented) {
  const SkyLight sky;
  EXPECT_NEAR(glm::length(sky({0, 0, 1}) - sky.zenith), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(sky({0, 0, -1}) - sky.ground), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(sky({-1, 0, 0}) - sky.horizon), 0.0, 1e-15);
  SkyLight no_sun = sky;
  no_sun.sun = glm::dvec3(0.0);
  EXPECT_NEAR(glm::length(sky(sky.sun_direction) - no_sun(sky.sun_direction) - sky.sun), 0.0, 1e-13);
  // Half-way to the rim, u = (cos(r/2) - cos r) / (1 - cos r).
  const double r = sky.sun_radius;
  const glm::dvec3 half_way =
      std::cos(r / 2) * sky.sun_direction + std::sin(r / 2) * glm::normalize(glm::cross(sky.sun_direction, {0, 0, 1}));
  const double u = (std::cos(r / 2) - std::cos(r)) / (1 - std::cos(r));
  EXPECT_NEAR(glm::length(sky(half_way) - no_sun(half_way) - u * u * sky.sun), 0.0, 1e-12);
  EXPECT_NEAR(sky.sun_direction.z, std::sin(40 * pi / 180), 1e-15);
  // Positive everywhere.
  for (const Sample& s : gauss_legendre_samples(40, 80)) {
    const glm::dvec3 l = sky(s.direction);
    EXPECT_GT(std::min({l.r, l.g, l.b}), 0.0);
  }
}

TEST(SkyLight, ExactCoefficientsAgreeWithQuadrature) {
  const SkyLight sky;
  const std::vector<glm::dvec3> exact = sky.coefficients(5);
  // Without the sun the sky is a quadratic in z: exact at 3 bands and zero above.
  SkyLight no_sun = sky;
  no_sun.sun = glm::dvec3(0.0);
  const SampleSet small(gauss_legendre_samples(5, 9), 5);
  const auto base = project_rgb([&](const glm::dvec3& w) { return no_sun(w); }, small);
  const auto base_exact = no_sun.coefficients(5);
  for (int i = 0; i < 25; ++i) EXPECT_NEAR(glm::length(base[i] - base_exact[i]), 0.0, 1e-13) << i;
  for (int i = 9; i < 25; ++i) EXPECT_NEAR(glm::length(base_exact[i]), 0.0, 1e-14) << i;
  // With it, the disc's rim limits a product rule to second order.
  const SampleSet fine(gauss_legendre_samples(200, 400), 5);
  const auto numeric = project_rgb([&](const glm::dvec3& w) { return sky(w); }, fine);
  for (int i = 0; i < 25; ++i) EXPECT_NEAR(glm::length(numeric[i] - exact[i]), 0.0, 1e-4) << i;
  // Sanity: c_0 / sqrt(4 pi) is the mean radiance, and the sun lifts the sunward side.
  EXPECT_GT(evaluate(exact, sky.sun_direction).r, evaluate(exact, -sky.sun_direction).r);
}

TEST(SkyLight, IrradianceFromTheSkyIsBrighterUpThanDown) {
  const std::vector<glm::dvec3> e = irradiance_coefficients(SkyLight{}.coefficients(3));
  EXPECT_GT(evaluate(e, {0, 0, 1}).b, evaluate(e, {0, 0, -1}).b);
}

}  // namespace
}  // namespace sh
