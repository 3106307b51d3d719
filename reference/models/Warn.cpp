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

class Warn final : public EvaluatedModel {
 public:
  Warn(const glm::dvec3& diffuse, const glm::dvec3& light_color, double exponent)
      : diffuse_(diffuse), light_color_(light_color), exponent_(exponent) {}

 private:
  glm::dvec3 evaluate(const SurfacePoint& point, const ObjectSpaceLighting& lighting, Report report) const override {
    const shading::PointLight light = shading::point_light(point, lighting);
    shading::report_point_light(report, point, lighting, light);
    report.direction("L", lighting.light_direction);
    const double cos_theta = glm::dot(light.direction, lighting.light_direction);
    report.scalar("Lp·L", cos_theta);
    report.scalar("sat(Lp·L)", sat(cos_theta));
    const double cone = std::pow(sat(cos_theta), exponent_);
    report.scalar("sat(Lp·L)^warn_exponent", cone);
    const double n_dot_l = glm::dot(point.normal, light.direction);
    report.scalar("N·Lp", n_dot_l);
    report.scalar("sat(N·Lp)", sat(n_dot_l));
    // Times 1/d twice: d² under- or overflows for d < ~1e-154 or > ~1e154, where the
    // colour itself is still a finite double.
    const double inverse_distance = 1.0 / light.distance;
    report.scalar("1/d", inverse_distance);
    if (report) report.scalar("1/d²", inverse_distance * inverse_distance);
    const double lit = cone * sat(n_dot_l);
    report.scalar("sat(Lp·L)^warn_exponent sat(N·Lp)", lit);
    const double factor = lit * inverse_distance * inverse_distance;
    report.scalar("sat(Lp·L)^warn_exponent sat(N·Lp)/d²", factor);
    if (report) report.colour("diffuse light_color", diffuse_ * light_color_);
    return diffuse_ * light_color_ * factor;
  }

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
