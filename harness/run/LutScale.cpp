#include "run/LutScale.h"

#include <algorithm>
#include <cmath>

namespace shaderbed {
namespace {

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
glm::dvec3 closest_point_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                     const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

}  // namespace

double lut_light_scale(const Case& c, const Mesh& mesh, const SceneSetup& scene) {
  auto colour = c.params.find("light_color");
  if (colour == c.params.end()) return 1.0;
  double diffuse = 1;
  if (auto d = c.params.find("diffuse"); d != c.params.end())
    diffuse = *std::max_element(d->second.begin(), d->second.end());
  const double intensity = *std::max_element(colour->second.begin(), colour->second.end());
  const glm::dvec3 light = glm::inverse(scene.world) * glm::dvec4(scene.lights.position, 1.0);
  double nearest = INFINITY;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a = mesh.vertices[mesh.indices[t]].position, b = mesh.vertices[mesh.indices[t + 1]].position,
                     c3 = mesh.vertices[mesh.indices[t + 2]].position;
    nearest = std::min(nearest, glm::distance(light, closest_point_on_triangle(light, a, b, c3)));
  }
  return diffuse * intensity / (nearest * nearest);
}

}  // namespace shaderbed
