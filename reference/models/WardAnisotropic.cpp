// Ward anisotropic (book §5.8.1, shaders §7.5.2, the Ch.7 half-vector form) with the
// directional light:
//   (D + spec) sat(N·L),
//   spec = S / (4 pi sx sy) / sqrt((N·L)(N·V)) exp(-2((H·X/sx)² + (H·Y/sy)²) / (1 + N·H)),
//   (sx, sy) = `roughness_xy`.
// The frame comes from the mesh tangent (errata E3): X = normalize(T - N(N·T)),
// Y = cross(N, X). Per vertex T is the vertex tangent; per pixel it is the tangent
// interpolated perspective-correctly, unnormalised (Render.cpp), which the
// orthogonalisation normalises anyway. 1/(4 pi sx sy) (errata E2); the specular term is 0
// unless N·L > 0 and N·V > 0 (errata E4).
#include <cmath>
#include <numbers>

#include "reference/Parameters.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

class WardAnisotropic final : public LightingModel {
 public:
  WardAnisotropic(const glm::dvec3& diffuse, const glm::dvec3& specular, const glm::dvec2& roughness)
      : diffuse_(diffuse),
        specular_(specular),
        roughness_(roughness),
        normalisation_(1.0 / (4.0 * std::numbers::pi * roughness.x * roughness.y)) {}

  glm::dvec3 shade(const SurfacePoint& point, const ObjectSpaceLighting& lighting) const override {
    const glm::dvec3& normal = point.normal;
    const glm::dvec3& to_light = lighting.light_direction;
    const glm::dvec3 to_eye = shading::to_eye(point, lighting);
    const double n_dot_l = glm::dot(normal, to_light);
    const double n_dot_v = glm::dot(normal, to_eye);
    const glm::dvec3 tangent_in_plane = point.tangent - normal * glm::dot(normal, point.tangent);
    glm::dvec3 spec(0.0);
    // X = normalize(T - N(N·T)) is undefined only when that projection is exactly zero
    // (T = 0 or T parallel to N); docs/errata.md: the specular term is 0 there. A short or
    // nearly parallel tangent still has a direction, normalised without under/overflow.
    // The GLUT meshes' tangents are perpendicular to their normals.
    if (n_dot_l > 0 && n_dot_v > 0 && tangent_in_plane != glm::dvec3(0.0)) {
      const glm::dvec3 x = stable::normalize(tangent_in_plane);
      const glm::dvec3 y = glm::cross(normal, x);
      const glm::dvec3 h = shading::half_vector(to_light, to_eye);
      const double hx = glm::dot(h, x) / roughness_.x;
      const double hy = glm::dot(h, y) / roughness_.y;
      const double lobe = std::exp(-2.0 * (hx * hx + hy * hy) / (1.0 + glm::dot(normal, h)));
      spec = specular_ * (normalisation_ * shading::inverse_sqrt_product(n_dot_l, n_dot_v) * lobe);
    }
    return (diffuse_ + spec) * sat(n_dot_l);
  }

 private:
  glm::dvec3 diffuse_;
  glm::dvec3 specular_;
  glm::dvec2 roughness_;
  double normalisation_;
};

}  // namespace

Params ward_aniso_defaults() {
  return {{"diffuse", {1, 1, 1}}, {"specular", {1, 1, 1}}, {"roughness_xy", {0.9, 0.1}}};
}

ModelOrError make_ward_aniso(const Params& params) {
  ParameterReader reader("ward_aniso", params);
  const glm::dvec3 diffuse = reader.colour("diffuse");
  const glm::dvec3 specular = reader.colour("specular");
  const glm::dvec2 roughness = reader.pair("roughness_xy");
  reader.require("roughness_xy", roughness.x > 0 && roughness.y > 0, "must be > 0 in both components (they divide)");
  if (auto error = reader.error()) return std::unexpected(*error);
  return std::make_unique<WardAnisotropic>(diffuse, specular, roughness);
}

}  // namespace reference
