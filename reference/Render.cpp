// render(): transform, rasterise, shade. Shading is deferred to one evaluation per
// covered pixel over the rasteriser's visibility buffer.
#include <algorithm>
#include <array>

#include "reference/ModelRegistry.h"
#include "reference/ObjectSpace.h"
#include "reference/Rasteriser.h"
#include "reference/SceneLighting.h"
#include "reference/Reference.h"

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

template <typename T>
T interpolate(const std::array<uint32_t, 3>& corners, const glm::dvec3& weights, const std::vector<T>& values) {
  return weights[0] * values[corners[0]] + weights[1] * values[corners[1]] + weights[2] * values[corners[2]];
}

// Per vertex: shade each vertex with its own (unit) normal; pixels interpolate colours.
std::vector<glm::dvec3> shade_vertices(const Mesh& mesh, const LightingModel& model,
                                       const ObjectSpaceLighting& lighting) {
  std::vector<glm::dvec3> colours;
  colours.reserve(mesh.vertices.size());
  for (const Vertex& vertex : mesh.vertices) {
    colours.push_back(
        model.shade({vertex.position, glm::normalize(vertex.normal), vertex.tangent, vertex.uv}, lighting));
  }
  return colours;
}

// Per pixel: interpolate the vertex attributes as given (like the varyings a vertex
// shader passes through), normalise the normal, shade.
glm::dvec3 shade_pixel(const Mesh& mesh, const std::array<uint32_t, 3>& corners, const glm::dvec3& weights,
                       const LightingModel& model, const ObjectSpaceLighting& lighting) {
  SurfacePoint point{};
  for (int i = 0; i < 3; ++i) {
    const Vertex& vertex = mesh.vertices[corners[i]];
    point.position += weights[i] * vertex.position;
    point.normal += weights[i] * vertex.normal;
    point.tangent += weights[i] * vertex.tangent;
    point.uv += weights[i] * vertex.uv;
  }
  point.normal = glm::normalize(point.normal);
  return model.shade(point, lighting);
}

}  // namespace

std::expected<Framebuffer, std::string> render(const Scene& scene, const std::string& model_name, Mode mode,
                                               const Params& params) {
  auto built = make_model(model_name, params);
  if (!built) return std::unexpected(built.error());
  auto model = with_scene_lighting(std::move(*built), model_name, scene.light, scene.ambient);
  if (!model) return std::unexpected(model.error());
  if (auto valid = check_scene(scene); !valid) return std::unexpected(valid.error());

  const Mesh& mesh = scene.mesh;
  const double aspect = double(scene.width) / scene.height;
  const glm::dmat4 object_to_clip = projection_matrix(scene.camera, aspect) * view_matrix(scene.camera) * scene.world;
  std::vector<glm::dvec4> clip_positions;
  clip_positions.reserve(mesh.vertices.size());
  for (const Vertex& vertex : mesh.vertices)
    clip_positions.push_back(object_to_clip * glm::dvec4(vertex.position, 1.0));

  const VisibilityBuffer visibility = rasterise(clip_positions, mesh.indices, scene.width, scene.height);
  const ObjectSpaceLighting lighting = to_object_space(scene.lights, scene.camera, scene.world);
  const std::vector<glm::dvec3> vertex_colours =
      mode == Mode::per_vertex ? shade_vertices(mesh, **model, lighting) : std::vector<glm::dvec3>{};

  const size_t pixel_count = static_cast<size_t>(scene.width) * scene.height;
  Framebuffer image{scene.width, scene.height, std::vector<double>(pixel_count * 4, 0.0),
                    std::vector<uint8_t>(pixel_count, 0)};
  for (size_t pixel = 0; pixel < pixel_count; ++pixel) {
    const VisibleSample& sample = visibility.samples[pixel];
    if (!sample.covered()) continue;
    const size_t first = size_t{sample.triangle} * 3;
    const std::array<uint32_t, 3> corners{mesh.indices[first], mesh.indices[first + 1], mesh.indices[first + 2]};
    const glm::dvec3 colour = mode == Mode::per_vertex ? interpolate(corners, sample.weights, vertex_colours)
                                                       : shade_pixel(mesh, corners, sample.weights, **model, lighting);
    image.rgba[pixel * 4 + 0] = colour.r;
    image.rgba[pixel * 4 + 1] = colour.g;
    image.rgba[pixel * 4 + 2] = colour.b;
    image.rgba[pixel * 4 + 3] = 1.0;  // covered; the models produce RGB only
    image.coverage[pixel] = 1;
  }
  return image;
}

}  // namespace reference
