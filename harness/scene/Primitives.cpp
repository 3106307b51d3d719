#include "scene/Primitives.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace shaderbed {
namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;

// Two triangles per grid quad, counter-clockwise seen from outside; quads that collapse
// to a triangle (at a pole or apex) emit just the one non-degenerate triangle.
void add_grid_triangles(Mesh& m, uint32_t first, int columns, int rows, bool collapse_first_row,
                        bool collapse_last_row) {
  const uint32_t stride = columns + 1;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      const uint32_t a = first + r * stride + c, b = a + 1, d = a + stride, e = d + 1;
      if (!(collapse_first_row && r == 0)) m.indices.insert(m.indices.end(), {a, d, b});
      if (!(collapse_last_row && r == rows - 1)) m.indices.insert(m.indices.end(), {b, d, e});
    }
}

// Every shape's vertex colour, from its normal, and its binormal (Mesh.h).
Mesh painted(Mesh m) {
  for (Vertex& v : m.vertices) v.color = vertex_colour_from_normal(v.normal);
  fill_binormals(m.vertices);
  return m;
}

}  // namespace

Mesh solid_sphere(float radius, int slices, int stacks) {
  Mesh m{.name = "sphere"};
  for (int i = 0; i <= stacks; ++i) {
    const float theta = std::numbers::pi_v<float> * i / stacks;   // from +z down to -z
    for (int j = 0; j <= slices; ++j) {
      const float phi = kTwoPi * j / slices;
      const glm::vec3 n{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
      m.vertices.push_back({radius * n, n, {-std::sin(phi), std::cos(phi), 0.0f},
                            {float(j) / slices, float(i) / stacks}});
    }
  }
  add_grid_triangles(m, 0, slices, stacks, true, true);
  return painted(std::move(m));
}

Mesh solid_cube(float size, int n) {
  Mesh m{.name = "cube"};
  const float h = size / 2;
  // Each face: normal, u axis, v axis (u x v = normal, so triangles face outwards).
  const glm::vec3 faces[6][3] = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}}, {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},
      {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}, {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
  };
  for (const auto& f : faces) {
    const uint32_t first = static_cast<uint32_t>(m.vertices.size());
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        const float u = float(j) / n, v = float(i) / n;
        const glm::vec3 p = h * f[0] + (u * 2 - 1) * h * f[1] + (v * 2 - 1) * h * f[2];
        m.vertices.push_back({p, f[0], f[1], {u, v}});
      }
    // Grid rows advance along v, columns along u: (a, b=a+u, d=a+v) is counter-clockwise
    // about u x v = normal.
    const uint32_t stride = n + 1;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const uint32_t a = first + i * stride + j, b = a + 1, d = a + stride, e = d + 1;
        m.indices.insert(m.indices.end(), {a, b, d, b, e, d});
      }
  }
  return painted(std::move(m));
}

Mesh solid_cone(float base, float height, int slices, int stacks) {
  Mesh m{.name = "cone"};
  // Bottom cap (z = 0, facing -z): centre then a ring.
  m.vertices.push_back({{0, 0, 0}, {0, 0, -1}, {1, 0, 0}, {0.5f, 0.5f}});
  for (int j = 0; j <= slices; ++j) {
    const float phi = kTwoPi * j / slices;
    const glm::vec3 p{base * std::cos(phi), base * std::sin(phi), 0};
    m.vertices.push_back({p, {0, 0, -1}, {1, 0, 0}, {0.5f + 0.5f * std::cos(phi), 0.5f + 0.5f * std::sin(phi)}});
  }
  for (int j = 0; j < slices; ++j)
    m.indices.insert(m.indices.end(), {0u, uint32_t(j + 2), uint32_t(j + 1)});
  // Side: rings from the base (z = 0) to the apex (radius 0), smooth normals.
  const float slant = std::sqrt(base * base + height * height);
  const float nz = base / slant, nr = height / slant;
  const uint32_t first = static_cast<uint32_t>(m.vertices.size());
  for (int i = 0; i <= stacks; ++i) {
    const float t = float(i) / stacks;
    for (int j = 0; j <= slices; ++j) {
      const float phi = kTwoPi * j / slices;
      const glm::vec3 p{base * (1 - t) * std::cos(phi), base * (1 - t) * std::sin(phi), height * t};
      m.vertices.push_back({p, {nr * std::cos(phi), nr * std::sin(phi), nz}, {-std::sin(phi), std::cos(phi), 0},
                            {float(j) / slices, t}});
    }
  }
  // Rows advance toward the apex; with (a, b, d) as (phi, phi+, up) the winding is
  // counter-clockwise seen from outside. The last row collapses to the apex.
  const uint32_t stride = slices + 1;
  for (int i = 0; i < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      const uint32_t a = first + i * stride + j, b = a + 1, d = a + stride, e = d + 1;
      m.indices.insert(m.indices.end(), {a, b, d});
      if (i != stacks - 1) m.indices.insert(m.indices.end(), {b, e, d});
    }
  return painted(std::move(m));
}

Mesh solid_torus(float inner_radius, float outer_radius, int sides, int rings) {
  Mesh m{.name = "torus"};
  for (int i = 0; i <= rings; ++i) {
    const float phi = kTwoPi * i / rings;   // around the z axis
    for (int j = 0; j <= sides; ++j) {
      const float psi = kTwoPi * j / sides;   // around the tube
      const glm::vec3 n{std::cos(psi) * std::cos(phi), std::cos(psi) * std::sin(phi), std::sin(psi)};
      const glm::vec3 centre{outer_radius * std::cos(phi), outer_radius * std::sin(phi), 0};
      m.vertices.push_back({centre + inner_radius * n, n, {-std::sin(phi), std::cos(phi), 0},
                            {float(i) / rings, float(j) / sides}});
    }
  }
  // Rows advance around z (phi), columns around the tube (psi): (a, d, b) is
  // counter-clockwise seen from outside, as on the sphere.
  add_grid_triangles(m, 0, sides, rings, false, false);
  return painted(std::move(m));
}

const std::vector<std::string>& shape_names() {
  static const std::vector<std::string> names{"sphere", "cube", "cone", "torus"};
  return names;
}

std::optional<Mesh> make_shape(const std::string& name, Tessellation t) {
  const bool high = t == Tessellation::high;
  if (name == "sphere") return solid_sphere(25.0f, high ? 64 : 16, high ? 32 : 8);
  if (name == "cube") return solid_cube(35.0f, high ? 8 : 1);
  if (name == "cone") return solid_cone(20.0f, 40.0f, high ? 64 : 16, high ? 32 : 8);
  if (name == "torus") return solid_torus(8.0f, 22.0f, high ? 32 : 12, high ? 64 : 24);
  return std::nullopt;
}

std::optional<Mesh> make_shape(const std::string& name, int slices) {
  if (slices < 4) return std::nullopt;
  if (name == "sphere") return solid_sphere(25.0f, slices, slices / 2);
  if (name == "cube") return solid_cube(35.0f, std::max(1, slices / 8));
  if (name == "cone") return solid_cone(20.0f, 40.0f, slices, slices / 2);
  if (name == "torus") return solid_torus(8.0f, 22.0f, slices / 2, slices);
  return std::nullopt;
}

}  // namespace shaderbed
