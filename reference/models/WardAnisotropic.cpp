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
#include "reference/models/Evaluated.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

class WardAnisotropic final : public EvaluatedModel {
 public:
  WardAnisotropic(const glm::dvec3& diffuse, const glm::dvec3& specular, const glm::dvec2& roughness)
      : diffuse_(diffuse),
        specular_(specular),
        roughness_(roughness),
        normalisation_(1.0 / (4.0 * std::numbers::pi * roughness.x * roughness.y)) {}

 private:
  glm::dvec3 evaluate(const SurfacePoint& point, const ObjectSpaceLighting& lighting, Report report) const override {
    const glm::dvec3& normal = point.normal;
    const glm::dvec3& to_light = lighting.light_direction;
    const glm::dvec3 to_eye = shading::to_eye(point, lighting);
    report.normal("N", normal);
    report.direction("L", to_light);
    report.direction("V", to_eye);
    const double n_dot_l = glm::dot(normal, to_light);
    const double n_dot_v = glm::dot(normal, to_eye);
    report.scalar("N·L", n_dot_l);
    report.scalar("N·V", n_dot_v);
    report.scalar("sat(N·L)", sat(n_dot_l));
    report.scalar("1/(4π σx σy)", normalisation_);
    const double n_dot_t = glm::dot(normal, point.tangent);
    report.scalar("N·T", n_dot_t);
    const glm::dvec3 tangent_in_plane = point.tangent - normal * n_dot_t;
    report.direction("T − N(N·T)", tangent_in_plane);
    glm::dvec3 spec(0.0);
    // X = normalize(T - N(N·T)) is undefined only when that projection is exactly zero
    // (T = 0 or T parallel to N); docs/errata.md: the specular term is 0 there. A short or
    // nearly parallel tangent still has a direction, normalised without under/overflow.
    // The GLUT meshes' tangents are perpendicular to their normals.
    if (n_dot_l > 0 && n_dot_v > 0 && tangent_in_plane != glm::dvec3(0.0)) {
      const glm::dvec3 x = stable::normalize(tangent_in_plane);
      const glm::dvec3 y = glm::cross(normal, x);
      const glm::dvec3 h = shading::half_vector(to_light, to_eye);
      report.direction("X", x);
      report.direction("Y", y);
      report.direction("H", h);
      const double h_dot_x = glm::dot(h, x), h_dot_y = glm::dot(h, y), n_dot_h = glm::dot(normal, h);
      report.scalar("H·X", h_dot_x);
      report.scalar("H·Y", h_dot_y);
      report.scalar("N·H", n_dot_h);
      const double hx = h_dot_x / roughness_.x;
      const double hy = h_dot_y / roughness_.y;
      report.scalar("H·X/σx", hx);
      report.scalar("H·Y/σy", hy);
      const double exponent = -2.0 * (hx * hx + hy * hy) / (1.0 + n_dot_h);
      report.scalar("−2((H·X/σx)² + (H·Y/σy)²)/(1 + N·H)", exponent);
      const double lobe = std::exp(exponent);
      report.scalar("exp(−2((H·X/σx)² + (H·Y/σy)²)/(1 + N·H))", lobe);
      const double inverse_sqrt = shading::inverse_sqrt_product(n_dot_l, n_dot_v);
      report.scalar("1/sqrt((N·L)(N·V))", inverse_sqrt);
      spec = specular_ * (normalisation_ * inverse_sqrt * lobe);
    }
    report.colour("specular", spec);
    const glm::dvec3 sum = diffuse_ + spec;
    report.colour("diffuse + specular", sum);
    return sum * sat(n_dot_l);
  }

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
