// GLUT-compatible shapes: counts from GLUT's parameters, unit normals, closed surfaces,
// outward winding.
#include <cmath>
#include <map>
#include <tuple>

#include <gtest/gtest.h>

#include "scene/Primitives.h"

namespace shaderbed {
namespace {

// Welds vertices by position (seams and poles duplicate them for UVs/normals) and
// checks every edge is shared by exactly two triangles, once in each direction.
void expect_closed_and_consistently_wound(const Mesh& m) {
  std::map<std::tuple<long, long, long>, uint32_t> welded;
  std::vector<uint32_t> id(m.vertices.size());
  for (size_t i = 0; i < m.vertices.size(); ++i) {
    const glm::vec3 p = m.vertices[i].position * 1e4f;
    auto key = std::make_tuple(std::lround(p.x), std::lround(p.y), std::lround(p.z));
    id[i] = welded.try_emplace(key, uint32_t(welded.size())).first->second;
  }
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (size_t t = 0; t < m.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = id[m.indices[t + e]], b = id[m.indices[t + (e + 1) % 3]];
      ASSERT_NE(a, b) << m.name << ": degenerate triangle " << t / 3;
      ++directed[{a, b}];
    }
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << m.name << ": edge used twice in the same direction";
    auto opposite = directed.find({edge.second, edge.first});
    EXPECT_TRUE(opposite != directed.end()) << m.name << ": open edge " << edge.first << "-" << edge.second;
  }
}

void expect_unit_normals_facing_out(const Mesh& m, glm::vec3 centre) {
  for (const Vertex& v : m.vertices) {
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f) << m.name;
    EXPECT_NEAR(glm::length(v.tangent), 1.0f, 1e-5f) << m.name;
  }
  // Geometric normal (by winding) agrees with the vertex normals: counter-clockwise
  // seen from outside.
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const Vertex &a = m.vertices[m.indices[t]], &b = m.vertices[m.indices[t + 1]], &c = m.vertices[m.indices[t + 2]];
    const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
    const glm::vec3 smooth = a.normal + b.normal + c.normal;
    EXPECT_GT(glm::dot(face, smooth), 0.0f) << m.name << " triangle " << t / 3;
  }
  (void)centre;
}

TEST(Primitives, SphereCountsFollowGlutParameters) {
  for (auto [slices, stacks] : {std::pair{16, 8}, {7, 5}, {64, 32}}) {
    const Mesh m = solid_sphere(2.0f, slices, stacks);
    EXPECT_EQ(m.vertices.size(), size_t((slices + 1) * (stacks + 1)));
    EXPECT_EQ(m.triangle_count(), size_t(2 * slices * (stacks - 1)));
    for (const Vertex& v : m.vertices) EXPECT_NEAR(glm::length(v.position), 2.0f, 1e-5f);
    expect_closed_and_consistently_wound(m);
    expect_unit_normals_facing_out(m, {});
  }
}

TEST(Primitives, CubeCountsAndFaces) {
  for (int n : {1, 3, 8}) {
    const Mesh m = solid_cube(2.0f, n);
    EXPECT_EQ(m.vertices.size(), size_t(6 * (n + 1) * (n + 1)));
    EXPECT_EQ(m.triangle_count(), size_t(12 * n * n));
    for (const Vertex& v : m.vertices) {
      const float extent = std::max({std::abs(v.position.x), std::abs(v.position.y), std::abs(v.position.z)});
      EXPECT_NEAR(extent, 1.0f, 1e-6f);
      EXPECT_NEAR(glm::dot(v.position, v.normal), 1.0f, 1e-6f) << "face normal points out of its face";
    }
    expect_closed_and_consistently_wound(m);
    expect_unit_normals_facing_out(m, {});
  }
}

TEST(Primitives, ConeCountsAndApex) {
  for (auto [slices, stacks] : {std::pair{16, 8}, {5, 1}}) {
    const Mesh m = solid_cone(1.0f, 3.0f, slices, stacks);
    EXPECT_EQ(m.vertices.size(), size_t((slices + 2) + (slices + 1) * (stacks + 1)));
    EXPECT_EQ(m.triangle_count(), size_t(2 * slices * stacks));
    float top = 0;
    for (const Vertex& v : m.vertices) top = std::max(top, v.position.z);
    EXPECT_FLOAT_EQ(top, 3.0f) << "GLUT's cone points along +z from a base at z = 0";
    expect_closed_and_consistently_wound(m);
    expect_unit_normals_facing_out(m, {});
  }
}

TEST(Primitives, TorusCountsAndRadii) {
  const Mesh m = solid_torus(0.5f, 2.0f, 12, 24);
  EXPECT_EQ(m.vertices.size(), size_t(13 * 25));
  EXPECT_EQ(m.triangle_count(), size_t(2 * 12 * 24));
  for (const Vertex& v : m.vertices) {
    const glm::vec2 ring = glm::normalize(glm::vec2(v.position)) * 2.0f;
    EXPECT_NEAR(glm::distance(v.position, glm::vec3(ring, 0)), 0.5f, 1e-5f);
  }
  expect_closed_and_consistently_wound(m);
  expect_unit_normals_facing_out(m, {});
}

TEST(Primitives, NamedShapesAtBothTessellations) {
  for (const std::string& name : shape_names()) {
    auto low = make_shape(name, Tessellation::low);
    auto high = make_shape(name, Tessellation::high);
    ASSERT_TRUE(low && high) << name;
    EXPECT_GT(high->triangle_count(), low->triangle_count()) << name;
  }
  EXPECT_FALSE(make_shape("teapot", Tessellation::low));
}

}  // namespace
}  // namespace shaderbed
