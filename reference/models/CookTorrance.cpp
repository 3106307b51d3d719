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
#include "reference/models/Evaluated.h"
#include "reference/models/Models.h"
#include "reference/models/Shading.h"

namespace reference {
namespace {

using shading::sat;

class CookTorrance final : public EvaluatedModel {
 public:
  CookTorrance(const glm::dvec3& diffuse, double gaussian_c, double slope_m, double fresnel_r0)
      : diffuse_(diffuse), gaussian_c_(gaussian_c), slope_m_(slope_m), fresnel_r0_(fresnel_r0) {}

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
    if (report) {
      report.scalar("sat(N·L)", sat(n_dot_l));
      report.scalar("sat(N·V)", sat(n_dot_v));
    }
    if (!(n_dot_l > 0 && n_dot_v > 0)) return glm::dvec3(0.0);

    // The facet angle a = acos(N·H) as atan2(|N × H|, N·H) from the unnormalised L + V:
    // acos near 1 loses half the digits, which a sharp lobe (small m) magnifies
    // (docs/hard-cases.md). 1 - V·H likewise from the angle between V and L + V, for
    // Fresnel at r0 = 0 near retro-reflection. An unnormalised N (the unnormalised_normal
    // counterfactual) keeps the literal acos(sat(N·H)).
    const glm::dvec3 sum = to_light + to_eye;
    report.direction("L+V", sum);
    const double sum_length = stable::length(sum);
    if (report) report.direction("H", sum / sum_length);
    double n_dot_h, angle;
    if (shading::normal_length(normal) == 1.0) {
      const double along = glm::dot(normal, sum);
      const double raw_n_dot_h = along / sum_length;
      report.scalar("N·H", raw_n_dot_h);
      n_dot_h = sat(raw_n_dot_h);
      angle = std::atan2(stable::length(glm::cross(normal, sum)), along);
    } else {
      const double raw_n_dot_h = glm::dot(normal, sum / sum_length);
      report.scalar("N·H", raw_n_dot_h);
      n_dot_h = sat(raw_n_dot_h);
      angle = shading::clamped_acos(n_dot_h);
    }
    report.scalar("sat(N·H)", n_dot_h);
    report.scalar("a", angle);
    // V·H > 0 (H lies between L and V); 1 - V·H = |V × S|² / (|S| (|S| + V·S)), S = L + V.
    const double v_along = glm::dot(to_eye, sum);
    const double v_dot_h = v_along / sum_length;
    const glm::dvec3 v_across = glm::cross(to_eye, sum);
    const double one_minus_v_dot_h = glm::dot(v_across, v_across) / (sum_length * (sum_length + v_along));
    report.scalar("V·H", v_dot_h);
    report.scalar("1 − V·H", one_minus_v_dot_h);

    const double angle_over_m = angle / slope_m_;
    report.scalar("a/m", angle_over_m);
    const double distribution = gaussian_c_ * std::exp(-angle_over_m * angle_over_m);
    report.scalar("D", distribution);
    const double masking = 2.0 * n_dot_h * n_dot_v / v_dot_h;
    const double shadowing = 2.0 * n_dot_h * n_dot_l / v_dot_h;
    report.scalar("2 (N·H)(N·V)/(V·H)", masking);
    report.scalar("2 (N·H)(N·L)/(V·H)", shadowing);
    const double geometry = std::max(0.0, std::min({1.0, masking, shadowing}));
    report.scalar("G", geometry);
    const double schlick = std::pow(one_minus_v_dot_h, 5.0);
    report.scalar("(1 − V·H)^5", schlick);
    const double fresnel = fresnel_r0_ + (1.0 - fresnel_r0_) * schlick;
    report.scalar("F", fresnel);
    const double fdg = fresnel * distribution * geometry;
    report.scalar("F D G", fdg);
    // Divided one dot at a time: (N·L)(N·V) underflows when both are grazing.
    const double brdf = fdg / n_dot_l / n_dot_v;
    report.scalar("F D G/((N·L)(N·V))", brdf);
    return diffuse_ * brdf;
  }

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
