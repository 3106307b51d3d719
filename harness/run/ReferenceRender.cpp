#include "run/ReferenceRender.h"

#include "reference/ModelRegistry.h"
#include "reference/Reference.h"
#include "reference/Surface.h"

namespace shaderbed {
reference::Scene reference_scene(const Mesh& mesh, const SceneSetup& s, const Case& c) {
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
  return scene;
}


Result<ReferenceImage> render_reference(const Mesh& mesh, const SceneSetup& s, const Case& c, LightingMode mode) {
  return render_reference(mesh, s, c, mode, reference::Perturbation{});
}

Result<ReferenceImage> render_reference(const Mesh& mesh, const SceneSetup& s, const Case& c, LightingMode mode,
                                        const reference::Perturbation& perturbation) {
  auto fb = reference::render(reference_scene(mesh, s, c), c.model,
                              mode == LightingMode::per_vertex ? reference::Mode::per_vertex : reference::Mode::per_pixel,
                              c.params, perturbation);
  if (!fb) return std::unexpected(Error{.message = fb.error(), .file = c.path, .stage = ErrorStage::reference});
  return ReferenceImage{fb->width, fb->height, std::move(fb->rgba), std::move(fb->coverage)};
}

Result<ReferenceImage> render_reference(const Mesh& mesh, const SceneSetup& s, const Case& c, LightingMode mode,
                                        const reference::LightingModel& model) {
  auto fb = reference::render(reference_scene(mesh, s, c), model,
                              mode == LightingMode::per_vertex ? reference::Mode::per_vertex : reference::Mode::per_pixel);
  if (!fb) return std::unexpected(Error{.message = fb.error(), .file = c.path, .stage = ErrorStage::reference});
  return ReferenceImage{fb->width, fb->height, std::move(fb->rgba), std::move(fb->coverage)};
}

reference::Scene surface_scene(const Mesh& mesh, const SceneSetup& s, const Case& c) {
  reference::Scene scene = reference_scene(mesh, s, c);
  // The point-light models shade with the point light whatever the case says.
  const reference::ModelInfo* model = reference::find_model(c.model);
  if (model && (model->light == reference::LightUse::point || model->light == reference::LightUse::spot))
    scene.light = reference::SceneLight::point;
  return scene;
}

Result<SurfaceSamples> render_surface_samples(const Mesh& mesh, const SceneSetup& s, const Case& c) {
  auto surface = reference::render_surface(surface_scene(mesh, s, c));
  if (!surface) return std::unexpected(Error{.message = surface.error(), .file = c.path, .stage = ErrorStage::reference});
  return surface_samples(*surface);
}

}  // namespace shaderbed
