#pragma once
// Indexed triangle mesh in object space, one interleaved vertex format for every shape
// so backends need a single vertex layout.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace shaderbed {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;    // unit length
  glm::vec3 tangent;   // unit length, along increasing u
  glm::vec2 uv;
  // Vertex colour (RGBA). The shapes paint it from the normal, (0.5 + 0.5 n, 1)
  // (vertex_colour_from_normal), so it varies over every shape and is known exactly;
  // other meshes keep white.
  glm::vec4 color{1, 1, 1, 1};
  // The third axis of the tangent frame, normal x tangent (BINORMAL, a bitangent), as
  // D3D9-era meshes carry it; fill_binormals() computes it from the other two.
  glm::vec3 binormal{0, 0, 0};
};
static_assert(sizeof(Vertex) == 72, "backends upload Vertex as a tightly packed 72-byte stride");

inline glm::vec4 vertex_colour_from_normal(const glm::vec3& n) { return {0.5f + 0.5f * n, 1.0f}; }

// Every vertex's binormal from its normal and tangent (unit when they are unit and orthogonal).
inline void fill_binormals(std::vector<Vertex>& vertices) {
  for (Vertex& v : vertices) v.binormal = glm::cross(v.normal, v.tangent);
}

// A case's explicit vertex input map, `[attributes.<language>]`: input name (or
// "location N") -> attribute word: position, normal, tangent, binormal (bitangent),
// texcoord (uv), color (colour).
using AttributeTable = std::map<std::string, std::string>;

// Per-vertex data beyond the fixed format, in a second vertex buffer: named 4-float
// streams (the SH transfer coefficients, CPCA cluster offsets and weights, harness/prt).
// Stream k of vertex v is values[(v * names.size() + k) * 4 ...]. A shader input reads one
// when the case maps it by name in [attributes.<language>], or is named so itself.
struct ExtraStreams {
  std::vector<std::string> names;
  std::vector<float> values;
  uint32_t stride_floats() const { return uint32_t(4 * names.size()); }
  bool empty() const { return names.empty(); }
};

struct Mesh {
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;   // triangle list
  ExtraStreams extra;
  size_t triangle_count() const { return indices.size() / 3; }
};

}  // namespace shaderbed
