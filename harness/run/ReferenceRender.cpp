#include "run/ReferenceRender.h"

#include "reference/Reference.h"

namespace shaderbed {

Result<ReferenceImage> render_reference(const Mesh& mesh, const SceneSetup& s, const Case& c, LightingMode mode) {
  reference::Scene scene;
  scene.mesh.indices = mesh.indices;
  scene.mesh.vertices.reserve(mesh.vertices.size());
  for (const Vertex& v : mesh.vertices)
    scene.mesh.vertices.push_back({glm::dvec3(v.position), glm::dvec3(v.normal), glm::dvec3(v.tangent), glm::dvec2(v.uv)});
  scene.world = s.world;
  scene.camera = {s.camera.eye, s.camera.target, s.camera.up, s.camera.fovy_degrees, s.camera.near_plane,
                  s.camera.far_plane};
  scene.lights = {s.lights.direction, s.lights.position};
  // The case's light and ambient term (`light`, `ambient`), as its uniforms see them.
  scene.light = c.light == CaseLight::point         ? reference::SceneLight::point
                : c.light == CaseLight::directional ? reference::SceneLight::directional
                                                    : reference::SceneLight::model_default;
  scene.ambient = c.ambient.value_or(s.lights.ambient);
  scene.width = s.width;
  scene.height = s.height;
  auto fb = reference::render(scene, c.model,
                              mode == LightingMode::per_vertex ? reference::Mode::per_vertex : reference::Mode::per_pixel,
                              c.params);
  if (!fb) return std::unexpected(Error{.message = fb.error(), .file = c.path, .stage = "reference"});
  return ReferenceImage{fb->width, fb->height, std::move(fb->rgba), std::move(fb->coverage)};
}

}  // namespace shaderbed
