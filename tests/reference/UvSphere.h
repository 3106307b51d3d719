#pragma once
// A UV sphere of radius 1 with unit vertex normals for the reference's own tests:
// (slices + 1) * (stacks + 1) vertices, 2 * slices * stacks triangles (those touching a
// pole have zero area and are dropped by the rasteriser). At low tessellation the
// interpolated normal inside a triangle is visibly shorter than 1.
#include <cmath>
#include <cstdint>
#include <numbers>

#include "reference/Reference.h"

namespace reference::test {

inline Mesh uv_sphere(int slices, int stacks) {
  Mesh mesh;
  for (int j = 0; j <= stacks; ++j) {
    const double theta = std::numbers::pi * j / stacks;
    for (int i = 0; i <= slices; ++i) {
      const double phi = 2 * std::numbers::pi * i / slices;
      const glm::dvec3 p(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      mesh.vertices.push_back({p, p, {-std::sin(phi), 0, std::cos(phi)}, {double(i) / slices, double(j) / stacks}});
    }
  }
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const auto a = static_cast<uint32_t>(j * (slices + 1) + i), b = a + 1, c = a + slices + 1, d = c + 1;
      for (uint32_t index : {a, b, c, b, d, c}) mesh.indices.push_back(index);
    }
  }
  return mesh;
}

}  // namespace reference::test
