// Cook-Torrance (book §5.8.3, shaders §7.7) with the directional light, the book's form
// without a separate Lambert term: diffuse F D G / ((N·L)(N·V)), for N·L > 0 and N·V > 0,
// else 0 (errata E6). With NdotH = sat(N·H):
//   D = c exp(-(a/m)²), a = acos(NdotH) (argument clamped, errata E9), Blinn's Gaussian;
//   G = min(1, 2 NdotH (N·V)/(V·H), 2 NdotH (N·L)/(V·H)), clamped at 0 (errata E6: V·H,
//       not the shader's N·H);
//   F = r0 + (1 - r0)(1 - V·H)^5 (errata E6: Schlick in V·H, not the shader's N·L).
// c = `gaussian_c`, m = `slope_m`, r0 = `fresnel_r0`; `diffuse` is the overall scale.
#include <cmath>

#include "reference/Parameters.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

class CookTorrance final : public LightingModel {
 public:
  CookTorrance(const glm::dvec3& diffuse, double gaussian_c, double slope_m, double fresnel_r0)
      : diffuse_(diffuse), gaussian_c_(gaussian_c), slope_m_(slope_m), fresnel_r0_(fresnel_r0) {}

  glm::dvec3 shade(const SurfacePoint& point, const ObjectSpaceLighting& lighting) const override {
    const glm::dvec3& normal = point.normal;
    const glm::dvec3& to_light = lighting.light_direction;
    const glm::dvec3 to_eye = shading::to_eye(point, lighting);
    const double n_dot_l = glm::dot(normal, to_light);
    const double n_dot_v = glm::dot(normal, to_eye);
    if (!(n_dot_l > 0 && n_dot_v > 0)) return glm::dvec3(0.0);

    // The facet angle a = acos(N·H) as atan2(|N × H|, N·H) from the unnormalised L + V:
    // acos near 1 loses half the digits, which a sharp lobe (small m) magnifies
    // (docs/hard-cases.md). 1 - V·H likewise from the angle between V and L + V, for
    // Fresnel at r0 = 0 near retro-reflection. An unnormalised N (the unnormalised_normal
    // counterfactual) keeps the literal acos(sat(N·H)).
    const glm::dvec3 sum = to_light + to_eye;
    const double sum_length = stable::length(sum);
    double n_dot_h, angle;
    if (shading::normal_length(normal) == 1.0) {
      const double along = glm::dot(normal, sum);
      n_dot_h = sat(along / sum_length);
      angle = std::atan2(stable::length(glm::cross(normal, sum)), along);
    } else {
      n_dot_h = sat(glm::dot(normal, sum / sum_length));
      angle = shading::clamped_acos(n_dot_h);
    }
    // V·H > 0 (H lies between L and V); 1 - V·H = |V × S|² / (|S| (|S| + V·S)), S = L + V.
    const double v_along = glm::dot(to_eye, sum);
    const double v_dot_h = v_along / sum_length;
    const glm::dvec3 v_across = glm::cross(to_eye, sum);
    const double one_minus_v_dot_h = glm::dot(v_across, v_across) / (sum_length * (sum_length + v_along));

    const double angle_over_m = angle / slope_m_;
    const double distribution = gaussian_c_ * std::exp(-angle_over_m * angle_over_m);
    const double geometry = std::max(
        0.0, std::min({1.0, 2.0 * n_dot_h * n_dot_v / v_dot_h, 2.0 * n_dot_h * n_dot_l / v_dot_h}));
    const double fresnel = fresnel_r0_ + (1.0 - fresnel_r0_) * std::pow(one_minus_v_dot_h, 5.0);
    // Divided one dot at a time: (N·L)(N·V) underflows when both are grazing.
    return diffuse_ * (fresnel * distribution * geometry / n_dot_l / n_dot_v);
  }

 private:
  glm::dvec3 diffuse_;
  double gaussian_c_;
  double slope_m_;
  double fresnel_r0_;
};

}  // namespace

Params cook_torrance_defaults() {
  return {{"diffuse", {1, 1, 1}}, {"gaussian_c", {0.5}}, {"slope_m", {0.5}}, {"fresnel_r0", {0.5}}};
}

ModelOrError make_cook_torrance(const Params& params) {
  ParameterReader reader("cook_torrance", params);
  const glm::dvec3 diffuse = reader.colour("diffuse");
  const double gaussian_c = reader.scalar("gaussian_c");
  const double slope_m = reader.scalar("slope_m");
  const double fresnel_r0 = reader.scalar("fresnel_r0");
  reader.require("slope_m", slope_m > 0, "must be > 0 (m divides the facet angle)");
  if (auto error = reader.error()) return std::unexpected(*error);
  return std::make_unique<CookTorrance>(diffuse, gaussian_c, slope_m, fresnel_r0);
}

}  // namespace reference
