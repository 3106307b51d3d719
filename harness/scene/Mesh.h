#pragma once
// Indexed triangle mesh in object space, one interleaved vertex format for every shape
// so backends need a single vertex layout.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace shaderbed {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;    // unit length
  glm::vec3 tangent;   // unit length, along increasing u
  glm::vec2 uv;
};
static_assert(sizeof(Vertex) == 44, "backends upload Vertex as a tightly packed 44-byte stride");

struct Mesh {
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;   // triangle list
  size_t triangle_count() const { return indices.size() / 3; }
};

}  // namespace shaderbed
