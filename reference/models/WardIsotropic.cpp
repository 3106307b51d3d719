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
      const double n_dot_h = glm::dot(normal, shading::half_vector(to_light, to_eye));
      const double tan_squared = (1.0 - n_dot_h * n_dot_h) / (n_dot_h * n_dot_h);
      spec = specular_ * (std::exp(-tan_squared / roughness_squared_) * normalisation_ / std::sqrt(n_dot_l * n_dot_v));
    }
    return (diffuse_ + spec) * sat(n_dot_l);
  }

 private:
  glm::dvec3 diffuse_;
  glm::dvec3 specular_;
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
