#pragma once
// Small helpers the models share, each one line of docs/models.md "Conventions".
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "reference/LightingModel.h"

namespace reference::shading {

// sat(x) = max(0, x).
inline double sat(double x) { return std::max(0.0, x); }

// acos with its argument clamped to [-1, 1]: a renormalised dot can exceed 1 by an ulp
// (errata E9).
inline double clamped_acos(double x) { return std::acos(std::clamp(x, -1.0, 1.0)); }

// V = normalize(eye_position - P).
inline glm::dvec3 to_eye(const SurfacePoint& point, const ObjectSpaceLighting& lighting) {
  return glm::normalize(lighting.eye_position - point.position);
}

// H = normalize(L + V).
inline glm::dvec3 half_vector(const glm::dvec3& to_light, const glm::dvec3& to_eye) {
  return glm::normalize(to_light + to_eye);
}

// R = normalize(2 N (N·L) - L).
inline glm::dvec3 reflection(const glm::dvec3& normal, const glm::dvec3& to_light) {
  return glm::normalize(2.0 * normal * glm::dot(normal, to_light) - to_light);
}

// The point light seen from P: Lp = normalize(light_position - P), d = |light_position - P|.
struct PointLight {
  glm::dvec3 direction;
  double distance;
};

inline PointLight point_light(const SurfacePoint& point, const ObjectSpaceLighting& lighting) {
  const glm::dvec3 to_light = lighting.light_position - point.position;
  const double distance = glm::length(to_light);
  return {to_light / distance, distance};
}

// The generalised attenuation's denominator A d² + B d + C (book §2.3.2), (A, B, C) =
// `attenuation`.
inline double attenuation_denominator(const glm::dvec3& attenuation, double distance) {
  return attenuation.x * distance * distance + attenuation.y * distance + attenuation.z;
}

}  // namespace reference::shading
