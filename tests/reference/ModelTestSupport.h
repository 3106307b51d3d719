#pragma once
// Helpers for the lighting-model tests: a model built once and shaded at local
// configurations (the conventions of reference::evaluate(), without rebuilding the model
// per call, for grids and integrals), directions by angle, and hemisphere integrals.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "reference/ModelRegistry.h"
#include "reference/Reference.h"

namespace reference::testing {

constexpr double pi = std::numbers::pi;
const glm::dvec3 z_axis{0, 0, 1};
const glm::dvec3 x_axis{1, 0, 0};

// The unit vector at polar angle theta from +z and azimuth phi from +x (degrees): the
// local frame of evaluate(), N = +z, T = +x.
inline glm::dvec3 direction(double theta_degrees, double phi_degrees = 0) {
  const double theta = theta_degrees * pi / 180, phi = phi_degrees * pi / 180;
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// The model `name` with `overrides` on top of its defaults, built once.
class Shader {
 public:
  Shader(const std::string& name, const Params& overrides = {}) : name_(name) {
    auto params = default_params(name);
    EXPECT_TRUE(params) << params.error();
    if (params) {
      for (const auto& [key, values] : overrides) (*params)[key] = values;
      auto model = make_model(name, *params);
      EXPECT_TRUE(model) << model.error();
      if (model) model_ = std::move(*model);
    }
  }

  // A directional-light model at the origin: light_vector = L, eye at V; normal and
  // tangent as given (not normalised here, so tests can hand over an ulp-long normal).
  glm::dvec3 operator()(const glm::dvec3& L, const glm::dvec3& V, const glm::dvec3& N = z_axis,
                        const glm::dvec3& T = x_axis) const {
    if (!model_) return glm::dvec3(NAN);
    return model_->shade({glm::dvec3(0.0), N, T, glm::dvec2(0.0)}, {L, 50.0 * L, V});
  }

  // Any point and lighting, e.g. the case scene's point light at (0, 50, 0).
  glm::dvec3 shade(const SurfacePoint& point, const ObjectSpaceLighting& lighting) const {
    if (!model_) return glm::dvec3(NAN);
    return model_->shade(point, lighting);
  }

  // The BRDF the colour implies, f = colour / (N·L) (red channel), for N·L > 0.
  double brdf(const glm::dvec3& L, const glm::dvec3& V, const glm::dvec3& N = z_axis,
              const glm::dvec3& T = x_axis) const {
    return (*this)(L, V, N, T).r / glm::dot(N, L);
  }

  const std::string& name() const { return name_; }

 private:
  std::string name_;
  std::unique_ptr<const LightingModel> model_;
};

// The integral of f over the upper hemisphere (N = +z), midpoint rule in (theta, phi)
// with the sin(theta) solid-angle weight.
inline double integrate_hemisphere(const std::function<double(const glm::dvec3&)>& f, int theta_steps = 128,
                                   int phi_steps = 256) {
  const double d_theta = pi / 2 / theta_steps, d_phi = 2 * pi / phi_steps;
  double sum = 0;
  for (int i = 0; i < theta_steps; ++i) {
    const double theta = (i + 0.5) * d_theta;
    const double sin_theta = std::sin(theta), cos_theta = std::cos(theta);
    double ring = 0;
    for (int j = 0; j < phi_steps; ++j) {
      const double phi = (j + 0.5) * d_phi;
      ring += f({sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta});
    }
    sum += ring * sin_theta;
  }
  return sum * d_theta * d_phi;
}

// Directional albedo rho(V) = ∫ f(L, V) cos(theta_L) dω_L: with f = colour / (N·L) that is
// the integral of the colour itself over the light directions of the upper hemisphere.
inline double directional_albedo(const Shader& shader, const glm::dvec3& V, int theta_steps = 128,
                                 int phi_steps = 256) {
  return integrate_hemisphere([&](const glm::dvec3& L) { return shader(L, V).r; }, theta_steps, phi_steps);
}

// evaluate() that must succeed (NaN otherwise, so the comparison fails too).
inline glm::dvec3 eval(const std::string& model, const Params& params, const glm::dvec3& L, const glm::dvec3& V,
                       const glm::dvec3& N = z_axis, const glm::dvec3& T = x_axis, double distance = 50) {
  const auto colour = evaluate(model, params, L, V, N, T, distance);
  EXPECT_TRUE(colour) << colour.error();
  return colour ? *colour : glm::dvec3(NAN);
}

inline glm::dvec3 eval(const std::string& model, const Params& params, const Configuration& configuration) {
  const auto colour = evaluate(model, params, configuration);
  EXPECT_TRUE(colour) << colour.error();
  return colour ? *colour : glm::dvec3(NAN);
}

inline void expect_colour_near(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance = 1e-12) {
  EXPECT_NEAR(actual.r, expected.r, tolerance);
  EXPECT_NEAR(actual.g, expected.g, tolerance);
  EXPECT_NEAR(actual.b, expected.b, tolerance);
}

// A grey colour parameter.
inline std::vector<double> grey(double v) { return {v, v, v}; }

inline std::vector<double> to_param(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

// The next double above 1: a renormalised dot that came out one ulp too long (errata E9).
inline double one_plus_ulp() { return std::nextafter(1.0, 2.0); }

}  // namespace reference::testing
