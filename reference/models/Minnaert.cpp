// Minnaert (book §5.7.2, shaders §7.4): D (sat(N·V) sat(N·L))^k sat(N·L), k =
// `minnaert_power` = m - 1. The shader's form with the irradiance factor (errata E5);
// each dot clamped before the product, so the unlit half is 0, not NaN (errata E10).
#include <cmath>

#include "reference/Parameters.h"
#include "reference/models/Evaluated.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

class Minnaert final : public EvaluatedModel {
 public:
  Minnaert(const glm::dvec3& diffuse, double power) : diffuse_(diffuse), power_(power) {}

 private:
  glm::dvec3 evaluate(const SurfacePoint& point, const ObjectSpaceLighting& lighting, Report report) const override {
    const glm::dvec3 to_eye = shading::to_eye(point, lighting);
    report.normal("N", point.normal);
    report.direction("L", lighting.light_direction);
    report.direction("V", to_eye);
    const double raw_n_dot_l = glm::dot(point.normal, lighting.light_direction);
    const double raw_n_dot_v = glm::dot(point.normal, to_eye);
    report.scalar("N·L", raw_n_dot_l);
    report.scalar("N·V", raw_n_dot_v);
    const double n_dot_l = sat(raw_n_dot_l);
    const double n_dot_v = sat(raw_n_dot_v);
    report.scalar("sat(N·L)", n_dot_l);
    report.scalar("sat(N·V)", n_dot_v);
    // The product of two grazing dots underflows (1e-200 · 1e-200) where its power need
    // not: then the power of each factor.
    const double product = n_dot_v * n_dot_l;
    report.scalar("sat(N·V) sat(N·L)", product);
    const double term = product >= 0x1p-960 || n_dot_v == 0.0 || n_dot_l == 0.0
                            ? std::pow(product, power_)
                            : std::pow(n_dot_v, power_) * std::pow(n_dot_l, power_);
    report.scalar("(sat(N·V) sat(N·L))^k", term);
    const double factor = term * n_dot_l;
    report.scalar("(sat(N·V) sat(N·L))^k sat(N·L)", factor);
    return diffuse_ * factor;
  }

  glm::dvec3 diffuse_;
  double power_;
};

}  // namespace

Params minnaert_defaults() { return {{"diffuse", {1, 1, 1}}, {"minnaert_power", {0.8}}}; }

ModelOrError make_minnaert(const Params& params) {
  ParameterReader reader("minnaert", params);
  const glm::dvec3 diffuse = reader.colour("diffuse");
  const double power = reader.scalar("minnaert_power");
  if (auto error = reader.error()) return std::unexpected(*error);
  return std::make_unique<Minnaert>(diffuse, power);
}

}  // namespace reference
