// Blinn-Phong (book §5.6.3, shaders §7.2.2): D sat(N·L) + S sat(N·H)^power with the
// directional light, H = normalize(L + V). As in the book (and Phong), the specular term
// is not gated by N·L (errata E7).
#include <cmath>

#include "reference/Parameters.h"
#include "reference/models/Evaluated.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

class BlinnPhong final : public EvaluatedModel {
 public:
  BlinnPhong(const glm::dvec3& diffuse, const glm::dvec3& specular, double power)
      : diffuse_(diffuse), specular_(specular), power_(power) {}

 private:
  glm::dvec3 evaluate(const SurfacePoint& point, const ObjectSpaceLighting& lighting, Report report) const override {
    const glm::dvec3& normal = point.normal;
    const glm::dvec3& to_light = lighting.light_direction;
    const glm::dvec3 to_eye = shading::to_eye(point, lighting);
    report.normal("N", normal);
    report.direction("L", to_light);
    report.direction("V", to_eye);
    // H = normalize(L + V) is undefined only where L + V is exactly zero (L = -V; the GPU
    // gives NaN). docs/errata.md: the reference takes N·H = 0 there, no highlight. Any
    // other sum, however short, has a direction: the facet angle comes from |N × (L + V)|
    // and N·(L + V), which need no normalisation, and (N·H)^n from 1 - N·H near the peak.
    const glm::dvec3 sum = to_light + to_eye;
    report.direction("L+V", sum);
    double highlight = std::pow(0.0, power_);
    if (sum != glm::dvec3(0.0) && shading::plain_power(power_)) {
      const glm::dvec3 half = stable::normalize(sum);
      report.direction("H", half);
      const double n_dot_h = glm::dot(normal, half);
      report.scalar("N·H", n_dot_h);
      report.scalar("sat(N·H)", sat(n_dot_h));
      highlight = std::pow(sat(n_dot_h), power_);
    } else if (sum != glm::dvec3(0.0)) {
      if (report) report.direction("H", stable::normalize(sum));
      const shading::FacetCosine n_dot_h = shading::facet_cosine(normal, shading::angle_between(normal, sum));
      report.scalar("N·H", n_dot_h.cos);
      report.scalar("sat(N·H)", sat(n_dot_h.cos));
      highlight = shading::power_near_one(n_dot_h.cos, n_dot_h.one_minus, power_);
    }
    report.scalar("sat(N·H)^power", highlight);
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

Params blinn_phong_defaults() { return {{"diffuse", {1, 1, 1}}, {"specular", {1, 1, 1}}, {"power", {7}}}; }

ModelOrError make_blinn_phong(const Params& params) {
  ParameterReader reader("blinn_phong", params);
  const glm::dvec3 diffuse = reader.colour("diffuse");
  const glm::dvec3 specular = reader.colour("specular");
  const double power = reader.scalar("power");
  if (auto error = reader.error()) return std::unexpected(*error);
  return std::make_unique<BlinnPhong>(diffuse, specular, power);
}

}  // namespace reference
