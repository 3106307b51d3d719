#pragma once
// Lights in SH (Ch. 8's test function, Ch. 9's D3DX lights, an analytic sky) and the
// irradiance convolution that turns light coefficients into diffuse lighting.
// Every direction is in the SH frame (z up) and points from the lit point toward the light.
// docs/sh.md states the normalisations and the exact lights a reference integrates.
#include <cstdint>
#include <expected>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "sh/Projection.h"
#include "sh/Sampling.h"

namespace sh {

// ---- (a) The book's test function (Eq. 13, Figs. 8.13/8.14) --------------------------------
// f(theta, phi) = max(0, 5 cos theta - 4) + max(0, -4 sin(theta - pi) cos(phi - 2.5) - 3),
// with the book's code's "5 cos theta" (Eq. 13 as printed drops the 5).
double book_test_function(double theta, double phi);
double book_test_function(const glm::dvec3& direction);
// Its projection as the book computes it: a grid x grid jittered set (Sampling.h).
std::vector<double> book_test_coefficients(int bands, int grid, std::uint64_t seed = default_seed);
// The exact coefficients. Both terms are zonal lobes, max(0, 5t - 4) about +z and
// max(0, 4t - 3) about (cos 2.5, sin 2.5, 0), so project_zonal integrates them exactly.
std::vector<double> book_test_coefficients_exact(int bands);

// ---- (d) Irradiance: convolution with the clamped cosine (Ramamoorthi & Hanrahan 2001) ------
// A_l = 2 pi * integral_0^1 t P_l(t) dt for l < bands: pi, 2 pi/3, pi/4, 0, -pi/24, 0, ...
// Irradiance-map coefficients are E_lm = A_l L_lm, and E(n) = sum E_lm y_lm(n) is the
// irradiance at normal n; a diffuse point of albedo rho reflects rho E(n) / pi.
std::vector<double> band_limited_irradiance_weights(int bands);
std::vector<double> irradiance_coefficients(std::span<const double> light);
std::vector<glm::dvec3> irradiance_coefficients(std::span<const glm::dvec3> light);
// The transfer function max(0, n . w) of an unshadowed point (8.2.4.2, without albedo/pi):
// A_l y_lm(n).
std::vector<double> clamped_cosine(int bands, const glm::dvec3& normal);
// D3DX's "CosWtInt" for any band count: sum over l < bands of (2l+1)/(4 pi) A_l, the
// irradiance at n = d from the truncated SH of a unit delta arriving along d:
// 0.25, 0.75, 1.0625, 1.0625, 0.96875, 0.96875, ... for 1, 2, 3, ... bands.
double directional_light_normalisation(int bands);

// ---- (b) D3DX lights ------------------------------------------------------------------------
// D3DXSHEvalDirectionalLight. Exact light: a delta arriving from `direction` with
// irradiance pi * colour at normal incidence, so an unshadowed diffuse point of albedo 1
// facing it reflects exactly `colour`. The SH (D3DX's normalisation) is the truncated
// projection of that delta rescaled so the truncated SH gives the same: coefficients
// = pi / directional_light_normalisation(bands) * y(direction) * colour.
struct DirectionalLight {
  glm::dvec3 direction;  // unit
  glm::dvec3 colour;

  glm::dvec3 irradiance() const;  // pi * colour: the delta's strength
  // Exact exit radiance of an unshadowed albedo-1 diffuse point: colour * max(0, n . d).
  glm::dvec3 exit_radiance(const glm::dvec3& normal) const;
  std::vector<glm::dvec3> coefficients(int bands) const;
};
// The direction is normalised; a zero or non-finite direction or colour is an error.
std::expected<DirectionalLight, std::string> make_directional_light(const glm::dvec3& direction,
                                                                    const glm::dvec3& colour);

// D3DXSHEvalConeLight. Exact light: constant radiance colour / sin^2(min(radius, pi/2))
// inside the cone of half-angle `radius` about `direction`, none outside; an albedo-1
// diffuse point facing the axis reflects exactly `colour`. Its SH is the exact projection
// of that radiance (no rescaling, unlike the directional light), so a small cone tends to
// pi y(d) colour = directional_light_normalisation(bands) times the directional light's SH.
// As D3DX, a radius below 1e-4 is the directional light (a jump by that factor).
struct ConeLight {
  static constexpr double directional_below = 1e-4;

  glm::dvec3 direction;  // unit
  double radius;         // half-angle in radians, [0, pi]
  glm::dvec3 colour;

  bool is_directional() const { return radius < directional_below; }
  glm::dvec3 radiance() const;                               // inside the cone
  glm::dvec3 operator()(const glm::dvec3& direction) const;  // the exact radiance function
  std::vector<glm::dvec3> coefficients(int bands) const;
};
std::expected<ConeLight, std::string> make_cone_light(const glm::dvec3& direction, double radius,
                                                      const glm::dvec3& colour);

// ---- (c) An analytic sky ---------------------------------------------------------------------
// Radiance L(w) = base(w.z) + sun * u^2 where
//   base(z) = horizon + (zenith - ground)/2 z + ((zenith + ground)/2 - horizon) z^2,
//     the quadratic through ground (z = -1, nadir), horizon (z = 0) and zenith (z = 1);
//   u = (w . s - cos r) / (1 - cos r) inside the sun's disc (angle to s below r), 0 outside:
//     a disc of angular radius r, brightest (`sun`) at its centre, fading smoothly (C^1) to
//     its rim. Both parts are zonal polynomials, so coefficients() is exact.
// The defaults: a blue zenith, a pale horizon, brown ground, a sun 40 degrees up.
struct SkyLight {
  glm::dvec3 zenith{0.20, 0.40, 0.90};
  glm::dvec3 horizon{0.80, 0.85, 0.90};
  glm::dvec3 ground{0.25, 0.20, 0.15};
  glm::dvec3 sun_direction = sun_at(40.0, 30.0);  // unit
  double sun_radius = 0.1;                        // radians (5.7 degrees)
  glm::dvec3 sun{40.0, 38.0, 34.0};

  // The unit direction at that elevation above the horizon and azimuth from +x toward +y.
  static glm::dvec3 sun_at(double elevation_degrees, double azimuth_degrees);

  glm::dvec3 operator()(const glm::dvec3& direction) const;
  std::vector<glm::dvec3> coefficients(int bands) const;
};

}  // namespace sh
