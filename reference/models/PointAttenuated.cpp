// Point light with the generalised attenuation (book §2.1, §2.3.2) and Lambert diffuse:
//   diffuse light_color sat(N·Lp) / (A d² + B d + C),
// Lp = normalize(light_position - P), d = |light_position - P|, (A, B, C) = `attenuation`.
#include "reference/Parameters.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

class PointAttenuated final : public EvaluatedModel {
 public:
  PointAttenuated(const glm::dvec3& diffuse, const glm::dvec3& light_color, const glm::dvec3& attenuation)
      : diffuse_(diffuse), light_color_(light_color), attenuation_(attenuation) {}

 private:
  glm::dvec3 evaluate(const SurfacePoint& point, const ObjectSpaceLighting& lighting, Report report) const override {
    const shading::PointLight light = shading::point_light(point, lighting);
    shading::report_point_light(report, point, lighting, light);
    const double n_dot_l = glm::dot(point.normal, light.direction);
    report.scalar("N·Lp", n_dot_l);
    report.scalar("sat(N·Lp)", sat(n_dot_l));
    const double denominator = shading::attenuation_denominator(attenuation_, light.distance);
    report.scalar("A d² + B d + C", denominator);
    if (report) report.scalar("attenuation", 1.0 / denominator);
    const double factor = sat(n_dot_l) / denominator;
    report.scalar("sat(N·Lp)/(A d² + B d + C)", factor);
    if (report) report.colour("diffuse light_color", diffuse_ * light_color_);
    return diffuse_ * light_color_ * factor;
  }

  glm::dvec3 diffuse_;
  glm::dvec3 light_color_;
  glm::dvec3 attenuation_;
};

}  // namespace

Params point_attenuated_defaults() {
  return {{"diffuse", {1, 1, 1}}, {"light_color", {1, 1, 1}}, {"attenuation", {0, 0.04, 0}}};
}

ModelOrError make_point_attenuated(const Params& params) {
  ParameterReader reader("point_attenuated", params);
  const glm::dvec3 diffuse = reader.colour("diffuse");
  const glm::dvec3 light_color = reader.colour("light_color");
  const glm::dvec3 attenuation = reader.triple("attenuation");
  if (auto error = reader.error()) return std::unexpected(*error);
  return std::make_unique<PointAttenuated>(diffuse, light_color, attenuation);
}

}  // namespace reference
