// Warn spotlight (book §1.6/§2.4.3, Ch.6 Diffuse_Warn): a point light at light_position
// shining along -light_vector with a cos^alpha cone and true inverse-square falloff:
//   diffuse light_color / d² sat(Lp·L)^warn_exponent sat(N·Lp).
// Both dots are clamped at 0 in every variant (errata E11). The pixel_lut variant is
// compared against this analytic form.
#include <cmath>

#include "reference/Parameters.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

class Warn final : public LightingModel {
 public:
  Warn(const glm::dvec3& diffuse, const glm::dvec3& light_color, double exponent)
      : diffuse_(diffuse), light_color_(light_color), exponent_(exponent) {}

  glm::dvec3 shade(const SurfacePoint& point, const ObjectSpaceLighting& lighting) const override {
    const shading::PointLight light = shading::point_light(point, lighting);
    const double cone = std::pow(sat(glm::dot(light.direction, lighting.light_direction)), exponent_);
    // Times 1/d twice: d² under- or overflows for d < ~1e-154 or > ~1e154, where the
    // colour itself is still a finite double.
    const double inverse_distance = 1.0 / light.distance;
    return diffuse_ * light_color_ *
           (cone * sat(glm::dot(point.normal, light.direction)) * inverse_distance * inverse_distance);
  }

 private:
  glm::dvec3 diffuse_;
  glm::dvec3 light_color_;
  double exponent_;
};

}  // namespace

Params warn_defaults() {
  return {{"diffuse", {1, 1, 1}}, {"light_color", {1000, 1000, 1000}}, {"warn_exponent", {10}}};
}

ModelOrError make_warn(const Params& params) {
  ParameterReader reader("warn", params);
  const glm::dvec3 diffuse = reader.colour("diffuse");
  const glm::dvec3 light_color = reader.colour("light_color");
  const double exponent = reader.scalar("warn_exponent");
  if (auto error = reader.error()) return std::unexpected(*error);
  return std::make_unique<Warn>(diffuse, light_color, exponent);
}

}  // namespace reference
