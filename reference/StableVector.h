#pragma once
// Lengths and normalisation that neither under- nor overflow: glm::length squares the
// components, so a vector shorter than ~1e-154 comes out 0 (and normalises to NaN) and
// one longer than ~1e154 comes out Inf. The common case keeps glm's arithmetic exactly;
// only when v·v leaves the safe range is the vector scaled by a power of two (exact)
// first.
#include <cmath>
#include <glm/glm.hpp>

namespace reference::stable {

namespace detail {

// Where v·v is computed without under/overflow mattering: the largest component's square
// is a normal double, and the smaller ones' lost bits lie far below its ulp.
inline bool safe_squared_length(double squared) { return squared >= 0x1p-960 && squared <= 0x1p960; }

// The rare paths, out of line so the common one stays small enough to inline: v scaled by
// a power of two (exact) so that its largest component is in [1, 2) first. A zero or
// non-finite vector is used as it is (NaN or Inf, as glm gives).
double scaled_length(const glm::dvec3& v);
glm::dvec3 scaled_normalize(const glm::dvec3& v);

}  // namespace detail

// |v|, Inf only when |v| itself exceeds the largest double.
inline double length(const glm::dvec3& v) {
  const double squared = glm::dot(v, v);
  return detail::safe_squared_length(squared) ? std::sqrt(squared) : detail::scaled_length(v);
}

// v / |v| for any finite non-zero v (NaN for a zero vector, as glm::normalize).
inline glm::dvec3 normalize(const glm::dvec3& v) {
  const double squared = glm::dot(v, v);
  if (detail::safe_squared_length(squared)) return v * (1.0 / std::sqrt(squared));  // glm::normalize's form
  return detail::scaled_normalize(v);
}

}  // namespace reference::stable
