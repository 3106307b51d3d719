#pragma once
// Small helpers the models share, each one line of docs/models.md "Conventions", in forms
// that stay accurate at the extremes (tiny roughness, grazing angles, huge or tiny
// distances): docs/errata.md, "The reference at the extremes".
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "reference/LightingModel.h"
#include "reference/StableVector.h"
#include "reference/models/Evaluated.h"

namespace reference::shading {

// sat(x) = max(0, x).
inline double sat(double x) { return std::max(0.0, x); }

// acos with its argument clamped to [-1, 1]: a renormalised dot can exceed 1 by an ulp
// (errata E9).
inline double clamped_acos(double x) { return std::acos(std::clamp(x, -1.0, 1.0)); }

// V = normalize(eye_position - P), or V as a perturbation gives it.
inline glm::dvec3 to_eye(const SurfacePoint& point, const ObjectSpaceLighting& lighting) {
  if (lighting.to_eye) return *lighting.to_eye;
  return stable::normalize(lighting.eye_position - point.position);
}

// H = normalize(L + V), defined whenever L + V is not exactly zero.
inline glm::dvec3 half_vector(const glm::dvec3& to_light, const glm::dvec3& to_eye) {
  return stable::normalize(to_light + to_eye);
}

// R = normalize(2 N (N·L) - L).
inline glm::dvec3 reflection(const glm::dvec3& normal, const glm::dvec3& to_light) {
  return stable::normalize(2.0 * normal * glm::dot(normal, to_light) - to_light);
}

// The angle between two directions a and b (any lengths) as (sin, cos), from |a × b| and
// a·b: near 0 the sine keeps full relative precision, where 1 - cos² or acos(cos) would
// cancel (docs/hard-cases.md: the facet angle near a sharp lobe's peak).
struct Angle {
  double sin;
  double cos;
  double tan() const { return sin / cos; }
  // 1 - cos without cancellation: sin² / (1 + cos).
  double one_minus_cos() const { return cos > 0 ? sin * sin / (1.0 + cos) : 1.0 - cos; }
};

inline Angle angle_between(const glm::dvec3& a, const glm::dvec3& b) {
  const double along = glm::dot(a, b);
  const double across = stable::length(glm::cross(a, b));
  const double scale = stable::length(glm::dvec3(along, across, 0.0));  // |a| |b|
  return {across / scale, along / scale};
}

// |N| for the facet-angle forms: 1 when N is unit to within rounding (the documented case:
// a normalised or rotated double vector has |N|² within a few ulps of 1; the threshold
// 1e-12 leaves room for a chain of such steps), else |N| itself, so an unnormalised
// normal (Perturbation::unnormalised_normal, a shader that forgot normalize(), |N| ~ 0.99)
// still scales N·H as the literal formula does.
inline double normal_length(const glm::dvec3& normal) {
  const double squared = glm::dot(normal, normal);
  return std::abs(squared - 1.0) <= 1e-12 ? 1.0 : std::sqrt(squared);
}

// N·H and 1 - N·H from the angle between N and H (given as L + V, any length): the
// cancellation-free form for a unit N, |N| cos(gamma) for an unnormalised one.
struct FacetCosine {
  double cos;           // N·H
  double one_minus;     // 1 - N·H
};

inline FacetCosine facet_cosine(const glm::dvec3& normal, const Angle& gamma) {
  const double length = normal_length(normal);
  if (length == 1.0) return {gamma.cos, gamma.one_minus_cos()};
  return {length * gamma.cos, 1.0 - length * gamma.cos};
}

// Up to this power, pow(c, n) of a c with a few ulps of error stays within 1e-13: the
// models keep their plain (faster) form there, the book's powers among them.
constexpr double plain_power_limit = 256;
inline bool plain_power(double n) { return std::abs(n) <= plain_power_limit; }

// c^n for c in [0, 1]; near c = 1 from 1 - c (given without cancellation), where
// pow(c, n) would turn c's last-ulp error into n ulps of the result.
inline double power_near_one(double c, double one_minus_c, double n) {
  if (c > 0.5 && n != 0) return std::exp(n * std::log1p(-one_minus_c));
  return std::pow(std::max(0.0, c), n);
}

// The point light seen from P: Lp = normalize(light_position - P), d = |light_position - P|;
// Lp as a perturbation gives it, when it does (ObjectSpaceLighting::to_light).
struct PointLight {
  glm::dvec3 direction;
  double distance;
};

inline PointLight point_light(const SurfacePoint& point, const ObjectSpaceLighting& lighting) {
  const glm::dvec3 to_light = lighting.light_position - point.position;
  if (lighting.to_light) return {*lighting.to_light, stable::length(to_light)};
  const double squared = glm::dot(to_light, to_light);
  // glm::length's form where the squares neither under- nor overflow; outside that (it
  // gave 0 or Inf at d = 1e-200 or 1e200, and NaN directions) the scaled forms, out of line.
  if (stable::detail::safe_squared_length(squared)) {
    const double distance = std::sqrt(squared);
    return {to_light / distance, distance};
  }
  return {stable::detail::scaled_normalize(to_light), stable::detail::scaled_length(to_light)};
}

// point_light()'s quantities: the unnormalised light_position − P, d and Lp, and N.
inline void report_point_light(Report report, const SurfacePoint& point, const ObjectSpaceLighting& lighting,
                               const PointLight& light) {
  if (!report) return;
  report.normal("N", point.normal);
  report.displacement("light_position−P", lighting.light_position - point.position);
  report.scalar("d", light.distance);
  report.direction("Lp", light.direction);
}

// The generalised attenuation's denominator A d² + B d + C (book §2.3.2), (A, B, C) =
// `attenuation`, as (A d + B) d + C: with A = 0 it is B d + C exactly, and A d² never
// overflows (or gives 0 · Inf) before the product that matters.
inline double attenuation_denominator(const glm::dvec3& attenuation, double distance) {
  return (attenuation.x * distance + attenuation.y) * distance + attenuation.z;
}

// 1 / sqrt(a b) for a, b > 0 without the product under- or overflowing.
inline double inverse_sqrt_product(double a, double b) {
  const double product = a * b;
  if (product >= 0x1p-960 && product <= 0x1p960) return 1.0 / std::sqrt(product);
  return 1.0 / std::sqrt(a) / std::sqrt(b);
}

}  // namespace reference::shading
