#pragma once
// Homogeneous clipping, before the perspective divide.
#include <array>
#include <glm/glm.hpp>

namespace reference {

// A vertex of a clipped polygon: its clip-space position and its barycentric weights
// with respect to the original triangle. Attributes are linear in clip space, so the
// weights are all a clipped vertex needs to carry; the caller interpolates whatever
// attributes it has with them.
struct ClipVertex {
  glm::dvec4 position;
  glm::dvec3 weights;
};

// Each plane can add at most one vertex to a convex polygon: 3 + 6 planes.
struct ClipPolygon {
  std::array<ClipVertex, 9> vertices;
  int size = 0;
};

// Clips a triangle against the near plane (z_clip >= 0, depth range [0, 1]), against
// w >= a small epsilon (so no divide by w <= 0 whatever the projection), and against a
// guard band |x|, |y| <= guard_band * w that keeps window coordinates small enough for
// exact 64-bit edge functions. A triangle inside every plane comes back unchanged, so
// on-screen geometry is rasterised from its own vertices. Like the GPU, there is no far
// clip: fragments beyond it fail the depth test against the cleared 1.0.
ClipPolygon clip_triangle(const std::array<ClipVertex, 3>& triangle, double guard_band);

}  // namespace reference
