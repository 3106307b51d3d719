// Spotlight (book §2.4) over the attenuated point light: the spot sits at light_position
// and points along -light_vector, so cos(theta) = Lp·L with L the directional light's
// vector (toward the light). With the penumbra corrected (errata E1, the D3D9 form):
//   s = 1 if cos(theta) >= cos_umbra, 0 if cos(theta) <= cos_penumbra, else
//       ((cos(theta) - cos_penumbra) / (cos_umbra - cos_penumbra))^falloff;
//   colour = diffuse light_color s sat(N·Lp) / (A d² + B d + C).
// The umbra test comes first, so cos_umbra <= cos_penumbra never divides by zero.
#include <cmath>

#include "reference/Parameters.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

class Spot final : public EvaluatedModel {
 public:
  Spot(const glm::dvec3& diffuse, const glm::dvec3& light_color, const glm::dvec3& attenuation, double cos_umbra,
       double cos_penumbra, double falloff)
      : diffuse_(diffuse),
        light_color_(light_color),
        attenuation_(attenuation),
        cos_umbra_(cos_umbra),
        cos_penumbra_(cos_penumbra),
        falloff_(falloff) {}

 private:
  glm::dvec3 evaluate(const SurfacePoint& point, const ObjectSpaceLighting& lighting, Report report) const override {
    const shading::PointLight light = shading::point_light(point, lighting);
    shading::report_point_light(report, point, lighting, light);
    report.direction("L", lighting.light_direction);
    const double cos_theta = glm::dot(light.direction, lighting.light_direction);
    report.scalar("Lp·L", cos_theta);
    double spot = 0.0;
    if (cos_theta >= cos_umbra_) {
      spot = 1.0;
    } else if (cos_theta > cos_penumbra_) {
      const double ramp = (cos_theta - cos_penumbra_) / (cos_umbra_ - cos_penumbra_);
      report.scalar("(cosθ − cos_penumbra)/(cos_umbra − cos_penumbra)", ramp);
      spot = std::pow(ramp, falloff_);
    }
    report.scalar("spot", spot);
    const double n_dot_l = glm::dot(point.normal, light.direction);
    report.scalar("N·Lp", n_dot_l);
    report.scalar("sat(N·Lp)", sat(n_dot_l));
    const double denominator = shading::attenuation_denominator(attenuation_, light.distance);
    report.scalar("A d² + B d + C", denominator);
    if (report) report.scalar("attenuation", 1.0 / denominator);
    const double lit = spot * sat(n_dot_l);
    report.scalar("spot sat(N·Lp)", lit);
    const double factor = lit / denominator;
    report.scalar("spot sat(N·Lp)/(A d² + B d + C)", factor);
    if (report) report.colour("diffuse light_color", diffuse_ * light_color_);
    return diffuse_ * light_color_ * factor;
  }

  glm::dvec3 diffuse_;
  glm::dvec3 light_color_;
  glm::dvec3 attenuation_;
  double cos_umbra_;
  double cos_penumbra_;
  double falloff_;
};

}  // namespace

Params spot_defaults() {
  return {{"diffuse", {1, 1, 1}},      {"light_color", {1, 1, 1}},  {"attenuation", {0, 0.04, 0}},
          {"cos_umbra", {0.9659}}, {"cos_penumbra", {0.8660}}, {"falloff", {1}}};
}

ModelOrError make_spot(const Params& params) {
  ParameterReader reader("spot", params);
  const glm::dvec3 diffuse = reader.colour("diffuse");
  const glm::dvec3 light_color = reader.colour("light_color");
  const glm::dvec3 attenuation = reader.triple("attenuation");
  const double cos_umbra = reader.scalar("cos_umbra");
  const double cos_penumbra = reader.scalar("cos_penumbra");
  const double falloff = reader.scalar("falloff");
  if (auto error = reader.error()) return std::unexpected(*error);
  return std::make_unique<Spot>(diffuse, light_color, attenuation, cos_umbra, cos_penumbra, falloff);
}

}  // namespace reference
