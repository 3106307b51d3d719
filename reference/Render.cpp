// render(): transform, rasterise, shade. Shading is deferred to one evaluation per
// covered pixel over the rasteriser's visibility buffer.
#include <algorithm>
#include <array>

#include "reference/ModelRegistry.h"
#include "reference/ObjectSpace.h"
#include "reference/Reference.h"
#include "reference/SceneLighting.h"
#include "reference/StableVector.h"
#include "reference/VisibleSurface.h"

namespace reference {
namespace {

template <typename T>
T interpolate(const std::array<uint32_t, 3>& corners, const glm::dvec3& weights, const std::vector<T>& values) {
  return weights[0] * values[corners[0]] + weights[1] * values[corners[1]] + weights[2] * values[corners[2]];
}

// The lighting one shaded point sees: the scene's, or the scene's under a perturbation.
// Built here, once per shaded point, so no model needs to know about perturbations.
class PointLighting {
 public:
  PointLighting(const ObjectSpaceLighting& lighting, const Perturbation& perturbation, LightUse light_use,
                SceneLight scene_light)
      : lighting_(lighting),
        perturbation_(perturbation),
        // Only the directional-light models take light_direction as L; the spot and Warn
        // lights take it as their axis, which L -> -L leaves alone.
        negate_direction_(perturbation.negate_light && light_use == LightUse::directional),
        point_lit_(light_use == LightUse::point || light_use == LightUse::spot ||
                   (light_use == LightUse::directional && scene_light == SceneLight::point)),
        directional_(light_use == LightUse::directional) {}

  ObjectSpaceLighting at(const glm::dvec3& position) const {
    ObjectSpaceLighting at_point = lighting_;
    if (negate_direction_) at_point.light_direction = -lighting_.light_direction;
    // Reflecting the point light through P flips Lp and keeps its distance; a model lit
    // by the directional light never reads the position, so this is harmless for it.
    if (perturbation_.negate_light) at_point.light_position = 2.0 * position - lighting_.light_position;
    if (perturbation_.negate_eye) at_point.eye_position = 2.0 * position - lighting_.eye_position;
    return at_point;
  }

  // at(position), with L and V taken from the triangle's corners as a vertex stage would
  // have passed them (Perturbation::interpolated_light_eye).
  ObjectSpaceLighting at(const glm::dvec3& position, const std::array<glm::dvec3, 3>& corners,
                         const glm::dvec3& weights) const {
    ObjectSpaceLighting at_point = at(position);
    if (!perturbation_.interpolated_light_eye) return at_point;
    glm::dvec3 to_light(0.0), to_eye(0.0);
    for (int i = 0; i < 3; ++i) {
      const ObjectSpaceLighting at_corner = at(corners[i]);
      to_light += weights[i] * (point_lit_ ? stable::normalize(at_corner.light_position - corners[i])
                                           : at_corner.light_direction);
      to_eye += weights[i] * stable::normalize(at_corner.eye_position - corners[i]);
    }
    at_point.to_eye = to_eye;
    if (point_lit_) at_point.to_light = to_light;
    else if (directional_) at_point.light_direction = to_light;
    return at_point;
  }

 private:
  ObjectSpaceLighting lighting_;
  Perturbation perturbation_;
  bool negate_direction_;
  bool point_lit_;     // L = normalize(light_position - P)
  bool directional_;   // L = light_direction
};

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

// The triangle's geometric normal, unit, on the side `towards` points to.
glm::dvec3 facet_normal(const std::array<glm::dvec3, 3>& corners, const glm::dvec3& towards) {
  const glm::dvec3 normal = stable::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
  return glm::dot(normal, towards) < 0 ? -normal : normal;
}

// Per pixel: interpolate the vertex attributes as given (like the varyings a vertex
// shader passes through), normalise the normal (unless the perturbation says not to, or
// replaces it with the facet's), shade.
glm::dvec3 shade_pixel(const Mesh& mesh, const VisibleSample& sample, const LightingModel& model,
                       const PointLighting& lighting, const Perturbation& perturbation) {
  SurfacePoint point = interpolate_surface(mesh, sample);
  const std::array<uint32_t, 3> indices = triangle_corners(mesh, sample);
  const std::array<glm::dvec3, 3> corners{mesh.vertices[indices[0]].position, mesh.vertices[indices[1]].position,
                                          mesh.vertices[indices[2]].position};
  if (perturbation.faceted_normal) point.normal = facet_normal(corners, point.normal);
  else if (!perturbation.unnormalised_normal) point.normal = stable::normalize(point.normal);
  return model.shade(point, lighting.at(point.position, corners, sample.weights));
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
  auto built = make_model(model_name, params);
  if (!built) return std::unexpected(built.error());
  auto model = with_scene_lighting(std::move(*built), model_name, scene.light, scene.ambient);
  if (!model) return std::unexpected(model.error());
  const ModelInfo* info = find_model(model_name);
  return render_with(scene, **model, info ? info->light : LightUse::none, mode, perturbation);
}

std::expected<Framebuffer, std::string> render(const Scene& scene, const LightingModel& model, Mode mode) {
  return render_with(scene, model, LightUse::none, mode, Perturbation{});
}

}  // namespace reference
