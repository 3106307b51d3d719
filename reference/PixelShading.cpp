#include "reference/PixelShading.h"

#include <utility>

#include "reference/SceneLighting.h"
#include "reference/VisibleSurface.h"

namespace reference {
namespace {

// The triangle's geometric normal, unit, on the side `towards` points to.
glm::dvec3 facet_normal(const std::array<glm::dvec3, 3>& corners, const glm::dvec3& towards) {
  const glm::dvec3 normal = stable::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
  return glm::dot(normal, towards) < 0 ? -normal : normal;
}

}  // namespace

std::expected<SceneModel, std::string> scene_model(const Scene& scene, const std::string& model_name,
                                                   const Params& params) {
  auto built = make_model(model_name, params);
  if (!built) return std::unexpected(built.error());
  auto model = with_scene_lighting(std::move(*built), model_name, scene.light, scene.ambient);
  if (!model) return std::unexpected(model.error());
  const ModelInfo* info = find_model(model_name);
  return SceneModel{std::move(*model), info ? info->light : LightUse::none};
}

PixelInput pixel_input(const Mesh& mesh, const VisibleSample& sample, const PointLighting& lighting,
                       const Perturbation& perturbation) {
  SurfacePoint point = interpolate_surface(mesh, sample);
  const std::array<uint32_t, 3> indices = triangle_corners(mesh, sample);
  const std::array<glm::dvec3, 3> corners{mesh.vertices[indices[0]].position, mesh.vertices[indices[1]].position,
                                          mesh.vertices[indices[2]].position};
  if (perturbation.faceted_normal) point.normal = facet_normal(corners, point.normal);
  else if (!perturbation.unnormalised_normal) point.normal = stable::normalize(point.normal);
  return {point, lighting.at(point.position, corners, sample.weights)};
}

}  // namespace reference
