#include "reference/VisibleSurface.h"

#include <vector>

namespace reference {
namespace {

std::expected<void, std::string> check_scene(const Scene& scene) {
  if (scene.width <= 0 || scene.height <= 0) {
    return std::unexpected("image size " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                           " is empty");
  }
  if (scene.mesh.indices.size() % 3 != 0) {
    return std::unexpected("mesh has " + std::to_string(scene.mesh.indices.size()) +
                           " indices, not a multiple of 3 (triangle list)");
  }
  const size_t vertex_count = scene.mesh.vertices.size();
  for (uint32_t index : scene.mesh.indices) {
    if (index >= vertex_count) {
      return std::unexpected("mesh index " + std::to_string(index) + " out of range (" + std::to_string(vertex_count) +
                             " vertices)");
    }
  }
  return {};
}

}  // namespace

std::expected<VisibilityBuffer, std::string> rasterise_scene(const Scene& scene) {
  if (auto valid = check_scene(scene); !valid) return std::unexpected(valid.error());
  const double aspect = double(scene.width) / scene.height;
  const glm::dmat4 object_to_clip = projection_matrix(scene.camera, aspect) * view_matrix(scene.camera) * scene.world;
  std::vector<glm::dvec4> clip_positions;
  clip_positions.reserve(scene.mesh.vertices.size());
  for (const Vertex& vertex : scene.mesh.vertices)
    clip_positions.push_back(object_to_clip * glm::dvec4(vertex.position, 1.0));
  return rasterise(clip_positions, scene.mesh.indices, scene.width, scene.height);
}

std::array<uint32_t, 3> triangle_corners(const Mesh& mesh, const VisibleSample& sample) {
  const size_t first = size_t{sample.triangle} * 3;
  return {mesh.indices[first], mesh.indices[first + 1], mesh.indices[first + 2]};
}

SurfacePoint interpolate_surface(const Mesh& mesh, const VisibleSample& sample) {
  const std::array<uint32_t, 3> corners = triangle_corners(mesh, sample);
  SurfacePoint point{};
  for (int i = 0; i < 3; ++i) {
    const Vertex& vertex = mesh.vertices[corners[i]];
    point.position += sample.weights[i] * vertex.position;
    point.normal += sample.weights[i] * vertex.normal;
    point.tangent += sample.weights[i] * vertex.tangent;
    point.uv += sample.weights[i] * vertex.uv;
  }
  return point;
}

}  // namespace reference
