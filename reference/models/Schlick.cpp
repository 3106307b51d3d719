// Schlick (book §5.8.2, shaders §7.6): D sat(N·L) + S t / (n - (n - 1) t), t = sat(R·V),
// with the directional light; the rational function replaces Phong's pow. Not gated by
// N·L (errata E7).
#include "reference/Parameters.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

class Schlick final : public LightingModel {
 public:
  Schlick(const glm::dvec3& diffuse, const glm::dvec3& specular, double power)
      : diffuse_(diffuse), specular_(specular), power_(power) {}

  glm::dvec3 shade(const SurfacePoint& point, const ObjectSpaceLighting& lighting) const override {
    const glm::dvec3& normal = point.normal;
    const glm::dvec3& to_light = lighting.light_direction;
    // t = sat(R·V); the denominator n - (n - 1) t = n (1 - t) + t with 1 - t from the
    // angle between R and V, which does not cancel near the mirror direction.
    // (Up to plain_power_limit the book's form: (n - 1) times t's rounding stays small.)
    const glm::dvec3 reflection = shading::reflection(normal, to_light);
    const glm::dvec3 to_eye = shading::to_eye(point, lighting);
    double highlight;
    if (shading::plain_power(power_)) {
      const double t = sat(glm::dot(reflection, to_eye));
      highlight = t / (power_ - (power_ - 1.0) * t);
    } else {
      const shading::Angle angle = shading::angle_between(reflection, to_eye);
      const double t = sat(angle.cos);
      const double one_minus_t = angle.cos > 0 ? angle.one_minus_cos() : 1.0;
      highlight = t / (power_ * one_minus_t + t);
    }
    return diffuse_ * sat(glm::dot(normal, to_light)) + specular_ * highlight;
  }

 private:
  glm::dvec3 diffuse_;
  glm::dvec3 specular_;
  double power_;
};

}  // namespace

Params schlick_defaults() { return {{"diffuse", {1, 1, 1}}, {"specular", {1, 1, 1}}, {"power", {7}}}; }

ModelOrError make_schlick(const Params& params) {
  ParameterReader reader("schlick", params);
  const glm::dvec3 diffuse = reader.colour("diffuse");
  const glm::dvec3 specular = reader.colour("specular");
  const double power = reader.scalar("power");
  // The denominator n - (n - 1) t = n (1 - t) + t is positive on t in [0, 1] only for n > 0.
  reader.require("power", power > 0, "must be > 0 (the denominator n - (n-1) t vanishes otherwise)");
  if (auto error = reader.error()) return std::unexpected(*error);
  return std::make_unique<Schlick>(diffuse, specular, power);
}

}  // namespace reference
