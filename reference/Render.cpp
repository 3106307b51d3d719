// render(): transform, rasterise, shade. Shading is deferred to one evaluation per
// covered pixel over the rasteriser's visibility buffer.
#include <algorithm>
#include <array>

#include "reference/ObjectSpace.h"
#include "reference/PixelShading.h"
#include "reference/Reference.h"
#include "reference/StableVector.h"
#include "reference/VisibleSurface.h"

namespace reference {
namespace {

template <typename T>
T interpolate(const std::array<uint32_t, 3>& corners, const glm::dvec3& weights, const std::vector<T>& values) {
  return weights[0] * values[corners[0]] + weights[1] * values[corners[1]] + weights[2] * values[corners[2]];
}

// Per vertex: shade each vertex with its own (unit) normal; pixels interpolate colours.
std::vector<glm::dvec3> shade_vertices(const Mesh& mesh, const LightingModel& model, const PointLighting& lighting) {
  std::vector<glm::dvec3> colours;
  colours.reserve(mesh.vertices.size());
  for (const Vertex& vertex : mesh.vertices) {
    colours.push_back(model.shade({vertex.position, stable::normalize(vertex.normal), vertex.tangent, vertex.uv},
                                  lighting.at(vertex.position)));
  }
  return colours;
}

// Per pixel: the point and lighting pixel_input() gives, shaded.
glm::dvec3 shade_pixel(const Mesh& mesh, const VisibleSample& sample, const LightingModel& model,
                       const PointLighting& lighting, const Perturbation& perturbation) {
  const PixelInput input = pixel_input(mesh, sample, lighting, perturbation);
  return model.shade(input.point, input.lighting);
}

}  // namespace

std::expected<Framebuffer, std::string> render(const Scene& scene, const std::string& model_name, Mode mode,
                                               const Params& params) {
  return render(scene, model_name, mode, params, Perturbation{});
}

namespace {

std::expected<Framebuffer, std::string> render_with(const Scene& scene, const LightingModel& model, LightUse light,
                                                    Mode mode, const Perturbation& perturbation) {
  auto visibility = rasterise_scene(scene);
  if (!visibility) return std::unexpected(visibility.error());

  const Mesh& mesh = scene.mesh;
  const PointLighting lighting(to_object_space(scene.lights, scene.camera, scene.world), perturbation, light,
                              scene.light);
  const std::vector<glm::dvec3> vertex_colours =
      mode == Mode::per_vertex ? shade_vertices(mesh, model, lighting) : std::vector<glm::dvec3>{};

  const size_t pixel_count = static_cast<size_t>(scene.width) * scene.height;
  Framebuffer image{scene.width, scene.height, std::vector<double>(pixel_count * 4, 0.0),
                    std::vector<uint8_t>(pixel_count, 0)};
  for (size_t pixel = 0; pixel < pixel_count; ++pixel) {
    const VisibleSample& sample = visibility->samples[pixel];
    if (!sample.covered()) continue;
    const glm::dvec3 colour = mode == Mode::per_vertex
                                  ? interpolate(triangle_corners(mesh, sample), sample.weights, vertex_colours)
                                  : shade_pixel(mesh, sample, model, lighting, perturbation);
    image.rgba[pixel * 4 + 0] = colour.r;
    image.rgba[pixel * 4 + 1] = colour.g;
    image.rgba[pixel * 4 + 2] = colour.b;
    image.rgba[pixel * 4 + 3] = 1.0;  // covered; the models produce RGB only
    image.coverage[pixel] = 1;
  }
  return image;
}

}  // namespace

std::expected<Framebuffer, std::string> render(const Scene& scene, const std::string& model_name, Mode mode,
                                               const Params& params, const Perturbation& perturbation) {
  auto model = scene_model(scene, model_name, params);
  if (!model) return std::unexpected(model.error());
  return render_with(scene, *model->model, model->light, mode, perturbation);
}

std::expected<Framebuffer, std::string> render(const Scene& scene, const LightingModel& model, Mode mode) {
  return render_with(scene, model, LightUse::none, mode, Perturbation{});
}

}  // namespace reference
