// Lights in SH (Lights.h). The D3DX normalisations follow DirectXMath's DirectXSH.cpp
// (XMSHEvalDirectionalLight, XMSHEvalConeLight), the open-source successor of D3DX's SH
// functions; docs/sh.md derives them.
#include "sh/Lights.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sh/Basis.h"

namespace sh {

namespace {

constexpr double pi = std::numbers::pi;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Per channel project_zonal of a profile whose colour factors out: colour * g(t).
void add_zonal(std::vector<glm::dvec3>& out, int bands, const glm::dvec3& axis, const glm::dvec3& colour,
               const std::function<double(double)>& g, double t0, int degree) {
  const std::vector<double> c = project_zonal(bands, axis, g, t0, degree);
  for (std::size_t i = 0; i < c.size(); ++i) out[i] += colour * c[i];
}

}  // namespace

// ---- (a) -----------------------------------------------------------------------------------

double book_test_function(double theta, double phi) {
  return std::max(0.0, 5.0 * std::cos(theta) - 4.0) +
         std::max(0.0, -4.0 * std::sin(theta - pi) * std::cos(phi - 2.5) - 3.0);
}

double book_test_function(const glm::dvec3& direction) {
  const glm::dvec3 d = glm::normalize(direction);
  return book_test_function(std::acos(std::clamp(d.z, -1.0, 1.0)), std::atan2(d.y, d.x));
}

std::vector<double> book_test_coefficients(int bands, int grid, std::uint64_t seed) {
  const SampleSet samples(jittered_samples(grid, seed), bands);
  return project([](const glm::dvec3& d) { return book_test_function(d); }, samples);
}

std::vector<double> book_test_coefficients_exact(int bands) {
  // -4 sin(theta - pi) cos(phi - 2.5) = 4 sin(theta) cos(phi - 2.5) = 4 (w . a).
  const glm::dvec3 a{std::cos(2.5), std::sin(2.5), 0.0};
  return add(project_zonal(bands, {0, 0, 1}, [](double t) { return 5.0 * t - 4.0; }, 0.8, 1),
             project_zonal(bands, a, [](double t) { return 4.0 * t - 3.0; }, 0.75, 1));
}

// ---- (d) -----------------------------------------------------------------------------------

std::vector<double> band_limited_irradiance_weights(int bands) {
  std::vector<double> weights = zonal_moments(bands, [](double t) { return t; }, 0.0, 1);
  for (double& w : weights) w *= 2.0 * pi;
  return weights;
}

std::vector<double> irradiance_coefficients(std::span<const double> light) {
  const int bands = band_count(light.size());
  const std::vector<double> a = band_limited_irradiance_weights(bands);
  std::vector<double> e(std::size_t(coefficient_count(bands)));
  for (int l = 0; l < bands; ++l)
    for (int m = -l; m <= l; ++m) e[index(l, m)] = a[l] * light[index(l, m)];
  return e;
}

std::vector<glm::dvec3> irradiance_coefficients(std::span<const glm::dvec3> light) {
  const int bands = band_count(light.size());
  const std::vector<double> a = band_limited_irradiance_weights(bands);
  std::vector<glm::dvec3> e(std::size_t(coefficient_count(bands)));
  for (int l = 0; l < bands; ++l)
    for (int m = -l; m <= l; ++m) e[index(l, m)] = a[l] * light[index(l, m)];
  return e;
}

std::vector<double> clamped_cosine(int bands, const glm::dvec3& normal) {
  return project_zonal(bands, normal, [](double t) { return t; }, 0.0, 1);
}

double directional_light_normalisation(int bands) {
  const std::vector<double> a = band_limited_irradiance_weights(bands);
  double sum = 0.0;
  for (int l = 0; l < bands; ++l) sum += (2.0 * l + 1.0) / (4.0 * pi) * a[l];
  return sum;
}

// ---- (b) -----------------------------------------------------------------------------------

glm::dvec3 DirectionalLight::irradiance() const { return pi * colour; }

glm::dvec3 DirectionalLight::exit_radiance(const glm::dvec3& normal) const {
  return colour * std::max(0.0, glm::dot(glm::normalize(normal), direction));
}

std::vector<glm::dvec3> DirectionalLight::coefficients(int bands) const {
  std::vector<double> y(std::size_t(coefficient_count(std::max(bands, 0))));
  basis_all(bands, direction, y);
  const glm::dvec3 scale = pi / directional_light_normalisation(bands) * colour;
  std::vector<glm::dvec3> c(y.size());
  for (std::size_t i = 0; i < y.size(); ++i) c[i] = y[i] * scale;
  return c;
}

std::expected<DirectionalLight, std::string> make_directional_light(const glm::dvec3& direction,
                                                                    const glm::dvec3& colour) {
  if (!finite(direction) || glm::length(direction) == 0.0)
    return std::unexpected("directional light: the direction must be finite and not zero");
  if (!finite(colour)) return std::unexpected("directional light: the colour must be finite");
  return DirectionalLight{glm::normalize(direction), colour};
}

glm::dvec3 ConeLight::radiance() const {
  // D3DX's 1 / sin^2: the cone's cosine-weighted solid angle on its axis is pi sin^2(radius)
  // up to pi/2, beyond which the facing hemisphere is full.
  const double s = std::sin(std::min(radius, pi / 2));
  return colour / (s * s);
}

glm::dvec3 ConeLight::operator()(const glm::dvec3& w) const {
  if (is_directional()) return glm::dvec3(0.0);  // a delta: see DirectionalLight
  return glm::dot(glm::normalize(w), direction) >= std::cos(radius) ? radiance() : glm::dvec3(0.0);
}

std::vector<glm::dvec3> ConeLight::coefficients(int bands) const {
  if (is_directional()) return DirectionalLight{direction, colour}.coefficients(bands);
  std::vector<glm::dvec3> c(std::size_t(coefficient_count(std::max(bands, 0))), glm::dvec3(0.0));
  add_zonal(c, bands, direction, radiance(), [](double) { return 1.0; }, std::cos(radius), 0);
  return c;
}

std::expected<ConeLight, std::string> make_cone_light(const glm::dvec3& direction, double radius,
                                                      const glm::dvec3& colour) {
  if (!finite(direction) || glm::length(direction) == 0.0)
    return std::unexpected("cone light: the direction must be finite and not zero");
  if (!std::isfinite(radius) || radius < 0.0 || radius > pi)
    return std::unexpected("cone light: the radius must be in [0, pi] radians, not " + std::to_string(radius));
  if (!finite(colour)) return std::unexpected("cone light: the colour must be finite");
  return ConeLight{glm::normalize(direction), radius, colour};
}

// ---- (c) -----------------------------------------------------------------------------------

glm::dvec3 SkyLight::sun_at(double elevation_degrees, double azimuth_degrees) {
  const double e = elevation_degrees * pi / 180.0, a = azimuth_degrees * pi / 180.0;
  return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

glm::dvec3 SkyLight::operator()(const glm::dvec3& direction) const {
  const glm::dvec3 w = glm::normalize(direction);
  const double z = w.z;
  glm::dvec3 radiance = horizon + 0.5 * (zenith - ground) * z + (0.5 * (zenith + ground) - horizon) * z * z;
  const double rim = std::cos(sun_radius);
  const double t = glm::dot(w, sun_direction);
  if (t > rim) {
    const double u = (t - rim) / (1.0 - rim);
    radiance += sun * (u * u);
  }
  return radiance;
}

std::vector<glm::dvec3> SkyLight::coefficients(int bands) const {
  std::vector<glm::dvec3> c(std::size_t(coefficient_count(std::max(bands, 0))), glm::dvec3(0.0));
  const glm::dvec3 up{0, 0, 1};
  add_zonal(c, bands, up, horizon, [](double) { return 1.0; }, -1.0, 0);
  add_zonal(c, bands, up, 0.5 * (zenith - ground), [](double t) { return t; }, -1.0, 1);
  add_zonal(c, bands, up, 0.5 * (zenith + ground) - horizon, [](double t) { return t * t; }, -1.0, 2);
  const double rim = std::cos(sun_radius);
  add_zonal(
      c, bands, sun_direction, sun,
      [rim](double t) {
        const double u = (t - rim) / (1.0 - rim);
        return u * u;
      },
      rim, 2);
  return c;
}

}  // namespace sh
