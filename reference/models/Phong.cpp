// Phong: I = D max(0, N·L) + S max(0, R·V)^n with the directional light (book §2.2,
// shaders §3.7-3.8). R = normalize(2N(N·L) - L), V = normalize(eye - P).
// As in the book's shaders, the specular term is not gated by N·L > 0, so a highlight
// can appear on the unlit side; the GPU shaders under test do the same.
#include <algorithm>
#include <cmath>

#include "reference/Parameters.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

class Phong final : public LightingModel {
 public:
  Phong(const glm::dvec3& diffuse, const glm::dvec3& specular, double power)
      : diffuse_(diffuse), specular_(specular), power_(power) {}

  glm::dvec3 shade(const SurfacePoint& point, const ObjectSpaceLighting& lighting) const override {
    const glm::dvec3& normal = point.normal;
    const glm::dvec3& to_light = lighting.light_direction;
    const double n_dot_l = glm::dot(normal, to_light);
    const glm::dvec3 reflection = shading::reflection(normal, to_light);
    // Above plain_power_limit, R·V and 1 - R·V from the angle between R and V, so a high
    // power near the mirror direction does not multiply R·V's last-ulp error
    // (docs/errata.md, the extremes).
    const glm::dvec3 to_eye = shading::to_eye(point, lighting);
    double highlight;
    if (shading::plain_power(power_)) {
      highlight = std::pow(std::max(0.0, glm::dot(reflection, to_eye)), power_);
    } else {
      const shading::Angle angle = shading::angle_between(reflection, to_eye);
      highlight = shading::power_near_one(angle.cos, angle.one_minus_cos(), power_);
    }
    return diffuse_ * std::max(0.0, n_dot_l) + specular_ * highlight;
  }

 private:
  glm::dvec3 diffuse_;
  glm::dvec3 specular_;
  double power_;
};

}  // namespace

Params phong_defaults() { return {{"diffuse", {1, 1, 1}}, {"specular", {1, 1, 1}}, {"power", {7}}}; }

ModelOrError make_phong(const Params& params) {
  ParameterReader reader("phong", params);
  const glm::dvec3 diffuse = reader.colour("diffuse");
  const glm::dvec3 specular = reader.colour("specular");
  const double power = reader.scalar("power");
  if (auto error = reader.error()) return std::unexpected(*error);
  return std::make_unique<Phong>(diffuse, specular, power);
}

}  // namespace reference
