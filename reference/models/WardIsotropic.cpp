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
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

class WardIsotropic final : public LightingModel {
 public:
  WardIsotropic(const glm::dvec3& diffuse, const glm::dvec3& specular, double roughness)
      : diffuse_(diffuse),
        specular_(specular),
        roughness_(roughness),
        roughness_squared_(roughness * roughness),
        normalisation_(1.0 / (4.0 * std::numbers::pi * roughness * roughness)) {}

  glm::dvec3 shade(const SurfacePoint& point, const ObjectSpaceLighting& lighting) const override {
    const glm::dvec3& normal = point.normal;
    const glm::dvec3& to_light = lighting.light_direction;
    const glm::dvec3 to_eye = shading::to_eye(point, lighting);
    const double n_dot_l = glm::dot(normal, to_light);
    const double n_dot_v = glm::dot(normal, to_eye);
    glm::dvec3 spec(0.0);
    if (n_dot_l > 0 && n_dot_v > 0) {
      // tan(gamma) = |N × H| / N·H from the unnormalised L + V: (1 - (N·H)²) cancels near
      // the peak, where a sharp lobe magnifies the lost digits (docs/hard-cases.md). An
      // unnormalised N (the unnormalised_normal counterfactual) keeps the literal form.
      const glm::dvec3 sum = to_light + to_eye;
      double exponent;  // tan²(gamma) / sigma²
      if (shading::normal_length(normal) == 1.0) {
        const double tan_over_sigma = stable::length(glm::cross(normal, sum)) / glm::dot(normal, sum) / roughness_;
        exponent = tan_over_sigma * tan_over_sigma;
      } else {
        const double n_dot_h = glm::dot(normal, shading::half_vector(to_light, to_eye));
        exponent = (1.0 - n_dot_h * n_dot_h) / (n_dot_h * n_dot_h) / roughness_squared_;
      }
      spec = specular_ * (std::exp(-exponent) * normalisation_ * shading::inverse_sqrt_product(n_dot_l, n_dot_v));
    }
    return (diffuse_ + spec) * sat(n_dot_l);
  }

 private:
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
