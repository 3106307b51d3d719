#include "reference/Clipping.h"

namespace reference {
namespace {

// Inside where dot(normal, position) - offset >= 0.
struct ClipPlane {
  glm::dvec4 normal;
  double offset;
};

constexpr double minimum_w = 1e-9;

double distance(const ClipPlane& plane, const glm::dvec4& position) {
  return glm::dot(plane.normal, position) - plane.offset;
}

ClipVertex lerp(const ClipVertex& from, const ClipVertex& to, double t) {
  return {from.position + t * (to.position - from.position), from.weights + t * (to.weights - from.weights)};
}

// One Sutherland-Hodgman pass.
ClipPolygon clip_against(const ClipPolygon& polygon, const ClipPlane& plane) {
  ClipPolygon result;
  for (int i = 0; i < polygon.size; ++i) {
    const ClipVertex& a = polygon.vertices[i];
    const ClipVertex& b = polygon.vertices[(i + 1) % polygon.size];
    const double da = distance(plane, a.position);
    const double db = distance(plane, b.position);
    if (da >= 0) result.vertices[result.size++] = a;
    if ((da >= 0) != (db >= 0)) {
      // Always interpolate from the inside vertex, so the two triangles sharing an edge
      // get bit-identical new vertices and stay watertight.
      result.vertices[result.size++] = da >= 0 ? lerp(a, b, da / (da - db)) : lerp(b, a, db / (db - da));
    }
  }
  return result;
}

}  // namespace

ClipPolygon clip_triangle(const std::array<ClipVertex, 3>& triangle, double guard_band) {
  const std::array<ClipPlane, 6> planes{{
      {{0, 0, 1, 0}, 0.0},            // near: z >= 0
      {{0, 0, 0, 1}, minimum_w},      // w >= epsilon
      {{1, 0, 0, guard_band}, 0.0},   // x >= -g w
      {{-1, 0, 0, guard_band}, 0.0},  // x <= g w
      {{0, 1, 0, guard_band}, 0.0},   // y >= -g w
      {{0, -1, 0, guard_band}, 0.0},  // y <= g w
  }};
  ClipPolygon polygon;
  for (const ClipVertex& vertex : triangle) polygon.vertices[polygon.size++] = vertex;
  for (const ClipPlane& plane : planes) {
    bool all_inside = true;
    for (int i = 0; i < polygon.size; ++i)
      all_inside = all_inside && distance(plane, polygon.vertices[i].position) >= 0;
    if (all_inside) continue;
    polygon = clip_against(polygon, plane);
    if (polygon.size < 3) return {};
  }
  return polygon;
}

}  // namespace reference
