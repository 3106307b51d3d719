// Phong: I = D max(0, N·L) + S max(0, R·V)^n with the directional light (book §2.2,
// shaders §3.7-3.8). R = normalize(2N(N·L) - L), V = normalize(eye - P).
// As in the book's shaders, the specular term is not gated by N·L > 0, so a highlight
// can appear on the unlit side; the GPU shaders under test do the same.
#include <algorithm>
#include <cmath>

#include "reference/Parameters.h"
#include "reference/models/Evaluated.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

class Phong final : public EvaluatedModel {
 public:
  Phong(const glm::dvec3& diffuse, const glm::dvec3& specular, double power)
      : diffuse_(diffuse), specular_(specular), power_(power) {}

 private:
  glm::dvec3 evaluate(const SurfacePoint& point, const ObjectSpaceLighting& lighting, Report report) const override {
    const glm::dvec3& normal = point.normal;
    const glm::dvec3& to_light = lighting.light_direction;
    report.normal("N", normal);
    report.direction("L", to_light);
    const double n_dot_l = glm::dot(normal, to_light);
    report.scalar("N·L", n_dot_l);
    const glm::dvec3 reflection = shading::reflection(normal, to_light);
    report.direction("R", reflection);
    // Above plain_power_limit, R·V and 1 - R·V from the angle between R and V, so a high
    // power near the mirror direction does not multiply R·V's last-ulp error
    // (docs/errata.md, the extremes).
    const glm::dvec3 to_eye = shading::to_eye(point, lighting);
    report.direction("V", to_eye);
    double highlight;
    if (shading::plain_power(power_)) {
      const double r_dot_v = glm::dot(reflection, to_eye);
      report.scalar("R·V", r_dot_v);
      const double t = std::max(0.0, r_dot_v);
      report.scalar("sat(R·V)", t);
      highlight = std::pow(t, power_);
    } else {
      const shading::Angle angle = shading::angle_between(reflection, to_eye);
      report.scalar("R·V", angle.cos);
      if (report) report.scalar("sat(R·V)", std::max(0.0, angle.cos));
      highlight = shading::power_near_one(angle.cos, angle.one_minus_cos(), power_);
    }
    report.scalar("sat(R·V)^power", highlight);
    const double lit = std::max(0.0, n_dot_l);
    report.scalar("sat(N·L)", lit);
    const glm::dvec3 diffuse = diffuse_ * lit;
    const glm::dvec3 specular = specular_ * highlight;
    report.colour("diffuse", diffuse);
    report.colour("specular", specular);
    return diffuse + specular;
  }

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
