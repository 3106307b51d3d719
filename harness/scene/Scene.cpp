#include "scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace shaderbed {
namespace {

std::vector<double> values(const glm::dvec4& v) { return {v.x, v.y, v.z, v.w}; }

template <int C, int R>
std::vector<double> values(const glm::mat<C, R, double>& m) {
  const double* p = glm::value_ptr(m);   // column-major, as the packer expects
  return std::vector<double>(p, p + C * R);
}

// A matrix under its name and with each suffix.
void add_matrix(NamedValues& out, const std::string& name, const glm::dmat4& m) {
  const glm::dmat4 inverse = glm::inverse(m);
  out[name] = values(m);
  out[name + "_inverse"] = values(inverse);
  out[name + "_transpose"] = values(glm::transpose(m));
  out[name + "_inverse_transpose"] = values(glm::transpose(inverse));
}

// A direction through `m` (w = 0), renormalised, as (x, y, z, 0).
glm::dvec4 direction(const glm::dmat4& m, const glm::dvec3& d) {
  return {glm::normalize(glm::dvec3(m * glm::dvec4(d, 0.0))), 0.0};
}

glm::dvec4 position(const glm::dmat4& m, const glm::dvec3& p) { return m * glm::dvec4(p, 1.0); }

}  // namespace

glm::dmat4 view_matrix(const Camera& c) { return glm::lookAtLH(c.eye, c.target, c.up); }

glm::dmat4 projection_matrix(const Camera& c, double aspect) {
  return glm::perspectiveLH_ZO(glm::radians(c.fovy_degrees), aspect, c.near_plane, c.far_plane);
}

NamedValues scene_quantities(const SceneSetup& s) {
  const double aspect = double(s.width) / s.height;
  const glm::dmat4 view = view_matrix(s.camera);
  // A clip-space shift (NDC units, times w) moves the whole image: D3D9's half-pixel offset.
  glm::dmat4 shift(1.0);
  shift[3] = glm::dvec4(s.clip_offset, 0.0, 1.0);
  const glm::dmat4 projection = shift * projection_matrix(s.camera, aspect);
  const glm::dmat4 world_view = view * s.world;
  NamedValues out;
  add_matrix(out, "world", s.world);
  add_matrix(out, "view", view);
  add_matrix(out, "projection", projection);
  add_matrix(out, "world_view", world_view);
  add_matrix(out, "view_projection", projection * view);
  add_matrix(out, "transform", projection * world_view);
  out["normal_matrix"] = values(glm::transpose(glm::inverse(glm::dmat3(s.world))));
  out["normal_matrix_view"] = values(glm::transpose(glm::inverse(glm::dmat3(world_view))));

  // Lights and eye in each space: object (no suffix), world, view.
  const glm::dmat4 identity(1.0);
  const glm::dmat4 inverse_world = glm::inverse(s.world);
  const std::pair<const char*, const glm::dmat4*> spaces[] = {{"", &inverse_world}, {"_world", &identity}, {"_view", &view}};
  for (const auto& [suffix, from_world] : spaces) {
    out[std::string("light_vector") + suffix] = values(direction(*from_world, s.lights.direction));
    out[std::string("light_position") + suffix] = values(position(*from_world, s.lights.position));
    out[std::string("eye_position") + suffix] = values(position(*from_world, s.camera.eye));
  }
  out["ambient_light"] = values(glm::dvec4(s.lights.ambient, 1.0));
  return out;
}

}  // namespace shaderbed
