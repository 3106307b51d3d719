// Blinn-Phong (book §5.6.3, shaders §7.2.2): D sat(N·L) + S sat(N·H)^power with the
// directional light, H = normalize(L + V). As in the book (and Phong), the specular term
// is not gated by N·L (errata E7).
#include <cmath>

#include "reference/Parameters.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

class BlinnPhong final : public LightingModel {
 public:
  BlinnPhong(const glm::dvec3& diffuse, const glm::dvec3& specular, double power)
      : diffuse_(diffuse), specular_(specular), power_(power) {}

  glm::dvec3 shade(const SurfacePoint& point, const ObjectSpaceLighting& lighting) const override {
    const glm::dvec3& normal = point.normal;
    const glm::dvec3& to_light = lighting.light_direction;
    const glm::dvec3 to_eye = shading::to_eye(point, lighting);
    // H is undefined when L = -V (normalize of a zero vector; the GPU gives NaN).
    // docs/models.md does not say; the reference takes N·H = 0 there, no highlight. The
    // scenes never reach it (the eye would have to look up at the light through the
    // surface); evaluate() can.
    const glm::dvec3 sum = to_light + to_eye;
    const double n_dot_h = glm::dot(sum, sum) < 1e-12 ? 0.0 : glm::dot(normal, glm::normalize(sum));
    return diffuse_ * sat(glm::dot(normal, to_light)) + specular_ * std::pow(sat(n_dot_h), power_);
  }

 private:
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
