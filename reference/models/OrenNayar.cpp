// Oren-Nayar (book §5.7.1, shaders §7.3), the Fosner form with the directional light:
//   D sat(N·L) (A + B cosC sin(alpha) tan(beta)),
//   A = 1 - 0.5 s/(s + 0.33), B = 0.45 s/(s + 0.09), s = sigma² (`roughness_sq`),
//   alpha = max(theta_i, theta_r), beta = min(theta_i, theta_r),
//   cosC = sat(normalize(V - N(N·V)) · normalize(L - N(N·L))).
// cosC = 0 when either projection's squared length is below 1e-12 (errata E8); acos
// arguments are clamped (errata E9). The pixel_lut variant is compared against this
// analytic form: the reference has no LUT.
#include <algorithm>
#include <cmath>

#include "reference/Parameters.h"
#include "reference/models/Evaluated.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

constexpr double min_projection_length_squared = 1e-12;

class OrenNayar final : public EvaluatedModel {
 public:
  OrenNayar(const glm::dvec3& diffuse, double roughness_sq)
      : diffuse_(diffuse),
        a_(1.0 - 0.5 * roughness_sq / (roughness_sq + 0.33)),
        b_(0.45 * roughness_sq / (roughness_sq + 0.09)) {}

 private:
  glm::dvec3 evaluate(const SurfacePoint& point, const ObjectSpaceLighting& lighting, Report report) const override {
    const glm::dvec3& normal = point.normal;
    const glm::dvec3& to_light = lighting.light_direction;
    const glm::dvec3 to_eye = shading::to_eye(point, lighting);
    report.normal("N", normal);
    report.direction("L", to_light);
    report.direction("V", to_eye);
    report.scalar("A", a_);
    report.scalar("B", b_);
    const double n_dot_l = glm::dot(normal, to_light);
    const double n_dot_v = glm::dot(normal, to_eye);
    report.scalar("N·L", n_dot_l);
    report.scalar("N·V", n_dot_v);
    if (report) {
      // The angles as the book's shader computes them; the model works with the cosines.
      const double theta_i = shading::clamped_acos(n_dot_l), theta_r = shading::clamped_acos(n_dot_v);
      report.scalar("sat(N·L)", sat(n_dot_l));
      report.scalar("θi", theta_i);
      report.scalar("θr", theta_r);
      report.scalar("α", std::max(theta_i, theta_r));
      report.scalar("β", std::min(theta_i, theta_r));
    }

    if (n_dot_l <= 0) return glm::dvec3(0.0);
    // sin(alpha) and tan(beta) from the cosines: alpha = max(theta) has the smaller
    // cosine, beta the larger. This is exact where tan(acos(x)) is not: near
    // N.L = 1e-15, acos loses the difference to pi/2 in its last ulp, and N.L tan(beta)
    // (which tends to 1) came out 1% off.
    const double cos_alpha = std::clamp(std::min(n_dot_l, n_dot_v), -1.0, 1.0);
    const double cos_beta = std::clamp(std::max(n_dot_l, n_dot_v), -1.0, 1.0);
    const double sin_alpha = std::sqrt(1 - cos_alpha * cos_alpha);
    const double tan_beta = std::sqrt(1 - cos_beta * cos_beta) / cos_beta;   // cos_beta >= N.L > 0
    report.scalar("cos α", cos_alpha);
    report.scalar("cos β", cos_beta);
    report.scalar("sin α", sin_alpha);
    report.scalar("tan β", tan_beta);

    const glm::dvec3 eye_in_plane = to_eye - normal * n_dot_v;
    const glm::dvec3 light_in_plane = to_light - normal * n_dot_l;
    report.direction("V − N(N·V)", eye_in_plane);
    report.direction("L − N(N·L)", light_in_plane);
    double cos_c = 0.0;
    if (glm::dot(eye_in_plane, eye_in_plane) >= min_projection_length_squared &&
        glm::dot(light_in_plane, light_in_plane) >= min_projection_length_squared) {
      const glm::dvec3 eye_direction = glm::normalize(eye_in_plane), light_direction = glm::normalize(light_in_plane);
      report.direction("normalize(V − N(N·V))", eye_direction);
      report.direction("normalize(L − N(N·L))", light_direction);
      const double projected = glm::dot(eye_direction, light_direction);
      report.scalar("cos(φr − φi)", projected);
      cos_c = sat(projected);
    }
    report.scalar("cosC", cos_c);
    if (report) report.scalar("sin α tan β", sin_alpha * tan_beta);
    const double factor = a_ + b_ * cos_c * sin_alpha * tan_beta;
    report.scalar("A + B cosC sin α tan β", factor);
    const double scale = n_dot_l * factor;
    report.scalar("sat(N·L) (A + B cosC sin α tan β)", scale);
    return diffuse_ * scale;
  }

  glm::dvec3 diffuse_;
  double a_;
  double b_;
};

}  // namespace

Params oren_nayar_defaults() { return {{"diffuse", {1, 1, 1}}, {"roughness_sq", {0.5}}}; }

ModelOrError make_oren_nayar(const Params& params) {
  ParameterReader reader("oren_nayar", params);
  const glm::dvec3 diffuse = reader.colour("diffuse");
  const double roughness_sq = reader.scalar("roughness_sq");
  reader.require("roughness_sq", roughness_sq >= 0, "must be >= 0 (it is sigma squared)");
  if (auto error = reader.error()) return std::unexpected(*error);
  return std::make_unique<OrenNayar>(diffuse, roughness_sq);
}

}  // namespace reference
