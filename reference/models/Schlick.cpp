// Schlick (book §5.8.2, shaders §7.6): D sat(N·L) + S t / (n - (n - 1) t), t = sat(R·V),
// with the directional light; the rational function replaces Phong's pow. Not gated by
// N·L (errata E7).
#include "reference/Parameters.h"
#include "reference/models/Evaluated.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

class Schlick final : public EvaluatedModel {
 public:
  Schlick(const glm::dvec3& diffuse, const glm::dvec3& specular, double power)
      : diffuse_(diffuse), specular_(specular), power_(power) {}

 private:
  glm::dvec3 evaluate(const SurfacePoint& point, const ObjectSpaceLighting& lighting, Report report) const override {
    const glm::dvec3& normal = point.normal;
    const glm::dvec3& to_light = lighting.light_direction;
    report.normal("N", normal);
    report.direction("L", to_light);
    // t = sat(R·V); the denominator n - (n - 1) t = n (1 - t) + t with 1 - t from the
    // angle between R and V, which does not cancel near the mirror direction.
    // (Up to plain_power_limit the book's form: (n - 1) times t's rounding stays small.)
    const glm::dvec3 reflection = shading::reflection(normal, to_light);
    const glm::dvec3 to_eye = shading::to_eye(point, lighting);
    report.direction("R", reflection);
    report.direction("V", to_eye);
    double highlight;
    if (shading::plain_power(power_)) {
      const double r_dot_v = glm::dot(reflection, to_eye);
      report.scalar("R·V", r_dot_v);
      const double t = sat(r_dot_v);
      report.scalar("t", t);
      const double denominator = power_ - (power_ - 1.0) * t;
      report.scalar("power − (power − 1) t", denominator);
      highlight = t / denominator;
    } else {
      const shading::Angle angle = shading::angle_between(reflection, to_eye);
      report.scalar("R·V", angle.cos);
      const double t = sat(angle.cos);
      report.scalar("t", t);
      const double one_minus_t = angle.cos > 0 ? angle.one_minus_cos() : 1.0;
      const double denominator = power_ * one_minus_t + t;
      report.scalar("power − (power − 1) t", denominator);
      highlight = t / denominator;
    }
    report.scalar("t / (power − (power − 1) t)", highlight);
    const double n_dot_l = glm::dot(normal, to_light);
    report.scalar("N·L", n_dot_l);
    report.scalar("sat(N·L)", sat(n_dot_l));
    const glm::dvec3 diffuse = diffuse_ * sat(n_dot_l);
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
