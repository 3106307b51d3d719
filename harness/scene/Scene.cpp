#include "scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace shaderbed {
namespace {

std::vector<float> floats(const glm::dvec4& v) { return {float(v.x), float(v.y), float(v.z), float(v.w)}; }

std::vector<float> floats(const glm::dmat4& m) {
  const double* p = glm::value_ptr(m);   // column-major, as the packer expects
  return std::vector<float>(p, p + 16);
}

}  // namespace

glm::dmat4 view_matrix(const Camera& c) { return glm::lookAtLH(c.eye, c.target, c.up); }

glm::dmat4 projection_matrix(const Camera& c, double aspect) {
  return glm::perspectiveLH_ZO(glm::radians(c.fovy_degrees), aspect, c.near_plane, c.far_plane);
}

NamedValues scene_quantities(const SceneSetup& s) {
  const double aspect = double(s.width) / s.height;
  const glm::dmat4 transform = projection_matrix(s.camera, aspect) * view_matrix(s.camera) * s.world;
  const glm::dmat4 inverse_world = glm::inverse(s.world);
  const glm::dvec4 light_vector{glm::normalize(glm::dvec3(inverse_world * glm::dvec4(s.lights.direction, 0.0))), 0.0};
  return {
      {"transform", floats(transform)},
      {"world", floats(s.world)},
      {"light_vector", floats(light_vector)},
      {"light_position", floats(inverse_world * glm::dvec4(s.lights.position, 1.0))},
      {"eye_position", floats(inverse_world * glm::dvec4(s.camera.eye, 1.0))},
  };
}

}  // namespace shaderbed
