// Point light with the generalised attenuation (book §2.1, §2.3.2) and Lambert diffuse:
//   diffuse light_color sat(N·Lp) / (A d² + B d + C),
// Lp = normalize(light_position - P), d = |light_position - P|, (A, B, C) = `attenuation`.
#include "reference/Parameters.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

class PointAttenuated final : public LightingModel {
 public:
  PointAttenuated(const glm::dvec3& diffuse, const glm::dvec3& light_color, const glm::dvec3& attenuation)
      : diffuse_(diffuse), light_color_(light_color), attenuation_(attenuation) {}

  glm::dvec3 shade(const SurfacePoint& point, const ObjectSpaceLighting& lighting) const override {
    const shading::PointLight light = shading::point_light(point, lighting);
    return diffuse_ * light_color_ *
           (sat(glm::dot(point.normal, light.direction)) /
            shading::attenuation_denominator(attenuation_, light.distance));
  }

 private:
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
