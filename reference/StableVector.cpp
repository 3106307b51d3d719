#include "reference/StableVector.h"

#include <algorithm>

namespace reference::stable::detail {
namespace {

glm::dvec3 scaled(const glm::dvec3& v, int& exponent) {
  const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  exponent = 0;
  if (!(largest > 0) || !std::isfinite(largest)) return v;
  exponent = std::ilogb(largest);
  return {std::ldexp(v.x, -exponent), std::ldexp(v.y, -exponent), std::ldexp(v.z, -exponent)};
}

}  // namespace

double scaled_length(const glm::dvec3& v) {
  int exponent = 0;
  const glm::dvec3 w = scaled(v, exponent);
  return std::ldexp(std::sqrt(glm::dot(w, w)), exponent);
}

glm::dvec3 scaled_normalize(const glm::dvec3& v) {
  int exponent = 0;
  const glm::dvec3 w = scaled(v, exponent);
  return w * (1.0 / std::sqrt(glm::dot(w, w)));
}

}  // namespace reference::stable::detail
