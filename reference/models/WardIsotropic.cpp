// Ward isotropic (book §5.8.1, shaders §7.5.1) with the directional light:
//   (D + spec) sat(N·L),
//   spec = S exp(-tan²gamma / sigma²) / (4 pi sigma²) / sqrt((N·L)(N·V)),
//   tan²gamma = (1 - (N·H)²) / (N·H)², sigma = `roughness`.
// Ward's 1/(4 pi sigma²) normalisation (errata E2); the specular term is 0 unless
// N·L > 0 and N·V > 0 (errata E4). The pixel_lut variant is compared against this
// analytic form.
#include <cmath>
#include <numbers>

#include "reference/Parameters.h"
#include "reference/models/Evaluated.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

class WardIsotropic final : public EvaluatedModel {
 public:
  WardIsotropic(const glm::dvec3& diffuse, const glm::dvec3& specular, double roughness)
      : diffuse_(diffuse),
        specular_(specular),
        roughness_(roughness),
        roughness_squared_(roughness * roughness),
        normalisation_(1.0 / (4.0 * std::numbers::pi * roughness * roughness)) {}

 private:
  glm::dvec3 evaluate(const SurfacePoint& point, const ObjectSpaceLighting& lighting, Report report) const override {
    const glm::dvec3& normal = point.normal;
    const glm::dvec3& to_light = lighting.light_direction;
    const glm::dvec3 to_eye = shading::to_eye(point, lighting);
    report.normal("N", normal);
    report.direction("L", to_light);
    report.direction("V", to_eye);
    const double n_dot_l = glm::dot(normal, to_light);
    const double n_dot_v = glm::dot(normal, to_eye);
    report.scalar("N·L", n_dot_l);
    report.scalar("N·V", n_dot_v);
    report.scalar("sat(N·L)", sat(n_dot_l));
    report.scalar("1/(4π σ²)", normalisation_);
    glm::dvec3 spec(0.0);
    if (n_dot_l > 0 && n_dot_v > 0) {
      // tan(gamma) = |N × H| / N·H from the unnormalised L + V: (1 - (N·H)²) cancels near
      // the peak, where a sharp lobe magnifies the lost digits (docs/hard-cases.md). An
      // unnormalised N (the unnormalised_normal counterfactual) keeps the literal form.
      const glm::dvec3 sum = to_light + to_eye;
      report.direction("L+V", sum);
      double exponent;  // tan²(gamma) / sigma²
      if (shading::normal_length(normal) == 1.0) {
        if (report) {
          const glm::dvec3 half = shading::half_vector(to_light, to_eye);
          report.direction("H", half);
          report.scalar("N·H", glm::dot(normal, half));
        }
        const double tan_gamma = stable::length(glm::cross(normal, sum)) / glm::dot(normal, sum);
        report.scalar("tan γ", tan_gamma);
        if (report) report.scalar("tan²γ", tan_gamma * tan_gamma);
        const double tan_over_sigma = tan_gamma / roughness_;
        exponent = tan_over_sigma * tan_over_sigma;
      } else {
        const glm::dvec3 half = shading::half_vector(to_light, to_eye);
        report.direction("H", half);
        const double n_dot_h = glm::dot(normal, half);
        report.scalar("N·H", n_dot_h);
        const double tan_squared = (1.0 - n_dot_h * n_dot_h) / (n_dot_h * n_dot_h);
        report.scalar("tan²γ", tan_squared);
        exponent = tan_squared / roughness_squared_;
      }
      report.scalar("tan²γ/σ²", exponent);
      const double lobe = std::exp(-exponent);
      report.scalar("exp(−tan²γ/σ²)", lobe);
      const double inverse_sqrt = shading::inverse_sqrt_product(n_dot_l, n_dot_v);
      report.scalar("1/sqrt((N·L)(N·V))", inverse_sqrt);
      spec = specular_ * (lobe * normalisation_ * inverse_sqrt);
    }
    report.colour("specular", spec);
    const glm::dvec3 sum = diffuse_ + spec;
    report.colour("diffuse + specular", sum);
    return sum * sat(n_dot_l);
  }

  glm::dvec3 diffuse_;
  glm::dvec3 specular_;
  double roughness_;
  double roughness_squared_;
  double normalisation_;
};

}  // namespace

Params ward_iso_defaults() { return {{"diffuse", {1, 1, 1}}, {"specular", {1, 1, 1}}, {"roughness", {0.25}}}; }

ModelOrError make_ward_iso(const Params& params) {
  ParameterReader reader("ward_iso", params);
  const glm::dvec3 diffuse = reader.colour("diffuse");
  const glm::dvec3 specular = reader.colour("specular");
  const double roughness = reader.scalar("roughness");
  reader.require("roughness", roughness > 0, "must be > 0 (sigma divides)");
  if (auto error = reader.error()) return std::unexpected(*error);
  return std::make_unique<WardIsotropic>(diffuse, specular, roughness);
}

}  // namespace reference
