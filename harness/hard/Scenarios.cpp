#include "hard/Scenarios.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "scene/Primitives.h"

namespace shaderbed::hard {
namespace {

// The book's eye direction (-100, 50, 0) as V; L chosen relative to it.
const glm::dvec3 kView = glm::normalize(glm::dvec3(-2, 1, 0));
const glm::dvec3 kPerpendicular = glm::normalize(glm::dvec3(1, 2, 0));   // L with L.V = 0

bool is_point_light(const std::string& model) {
  return model == "point_attenuated" || model == "spot" || model == "warn";
}

// The parameter that makes a model's specular lobe as sharp as the issue asks, or none.
std::map<std::string, std::vector<double>> sharp_params(const std::string& model) {
  if (model == "phong" || model == "blinn_phong" || model == "schlick") return {{"power", {1e4}}};
  if (model == "cook_torrance") return {{"slope_m", {0.001}}};
  if (model == "ward_iso") return {{"roughness", {0.001}}};
  if (model == "ward_aniso") return {{"roughness_xy", {0.001, 0.001}}};
  return {};
}

// The lobe parameter's range for the half-angle map, broad (top row) to sharpest (bottom).
struct LobeRange {
  std::string param;
  double broad = 0, sharp = 0;
};
std::optional<LobeRange> lobe_range(const std::string& model) {
  if (model == "phong" || model == "blinn_phong" || model == "schlick") return LobeRange{"power", 1, 1e4};
  if (model == "cook_torrance") return LobeRange{"slope_m", 1, 1e-3};
  if (model == "ward_iso") return LobeRange{"roughness", 0.5, 1e-3};
  if (model == "ward_aniso") return LobeRange{"roughness_xy", 0.5, 1e-3};
  return std::nullopt;
}

// Half-width of the lobe slice: ~5 lobe widths. Power 1e4 has cos^n(2a) = e^-1 at
// a = 0.007; m = 0.001 has exp(-(a/m)^2) = e^-25 at a = 0.005.
double lobe_radius(const std::string& model) {
  return (model == "phong" || model == "blinn_phong" || model == "schlick") ? 0.02 : 0.005;
}

SliceSpec sphere(const glm::dvec3& to_light) { return SliceSpec{.to_light = to_light, .to_eye = kView}; }

// A camera aimed at `target` from the book's eye direction, with a field of view that
// frames `extent` object units across.
SceneSetup zoomed(const glm::dvec3& target, double extent) {
  SceneSetup s;
  s.camera.target = target;
  s.camera.eye = target + glm::dvec3(-100, 50, 0);
  const double distance = glm::length(s.camera.eye - target);
  s.camera.fovy_degrees = glm::degrees(2 * std::atan(0.5 * extent / distance));
  s.camera.near_plane = 0.5 * distance;
  s.camera.far_plane = 2 * distance;
  s.lights.position = target + glm::dvec3(0, 50, 0);
  return s;
}

}  // namespace

std::vector<Scenario> scenarios_for(const std::string& model, int size) {
  (void)size;
  std::vector<Scenario> out;
  out.push_back({"sphere_perpendicular",
                 "every normal with L perpendicular to V: N.L and N.V through 0 (grazing), N = V (Oren-Nayar's "
                 "degenerate projection), N.H = 0, the back side",
                 sphere(kPerpendicular), std::nullopt, {}});
  out.push_back({"sphere_opposite", "L = -V: H = normalize(L + V) undefined (exactly at the centre pixel)",
                 sphere(-kView), std::nullopt, {}});
  out.push_back({"sphere_coincident", "L = V (retro-reflection): N.L = N.V everywhere, both grazing together",
                 sphere(kView), std::nullopt, {}});
  {
    SliceSpec s = sphere(kPerpendicular);
    s.long_normals = true;
    out.push_back({"long_normals",
                   "normal attributes of length 1 + 1e-6 .. 1e-4: dots beyond [-1, 1] where the normal is not "
                   "renormalised (vertex variants, acos/sqrt(1 - x^2))",
                   s, std::nullopt, {}});
  }
  if (auto sharp = sharp_params(model); !sharp.empty()) {
    out.push_back({"sphere_sharp", "the whole sphere of normals with the sharpest lobe (power 1e4, m = 0.001, alpha = 0.001)",
                   sphere(kPerpendicular), std::nullopt, sharp});
    SliceSpec lobe = sphere(kPerpendicular);
    lobe.layout = NormalLayout::lobe;
    lobe.lobe_radius = lobe_radius(model);
    out.push_back({"lobe_sharp", "normals within a few lobe widths of H: the peak of the sharpest lobe, N.H -> 1",
                   lobe, std::nullopt, sharp});
  }
  if (auto range = lobe_range(model)) {
    SliceSpec map = sphere(kPerpendicular);
    map.layout = NormalLayout::half_angle;
    map.row_param = range->param;
    map.row_first = range->broad;
    map.row_last = range->sharp;
    out.push_back({"lobe_map",
                   "x = angle between N and H (log, 1e-5 to 1.5 rad), y = " + range->param +
                       " (log, broad at the top to sharpest at the bottom): where in the lobe, and from which "
                       "sharpness on, a formula loses precision",
                   map, std::nullopt, {}});
  }
  if (is_point_light(model)) {
    SliceSpec near{.layout = NormalLayout::plane, .plane_normal = glm::dvec3(0, 1, 0), .light_height = 1e-6};
    near.to_eye = kView;
    out.push_back({"light_near", "point light 1e-6 above the surface: distance -> 0, 1/d and 1/d^2 large",
                   near, std::nullopt, {}});
    SliceSpec on = near;
    on.light_height = 0;
    out.push_back({"light_on_surface",
                   "point light on the surface: d = 0 at the centre pixel (the model is undefined there)", on,
                   std::nullopt, {}});
  }
  // Geometry: the cone's apex (normals of one point in every direction around it) and a
  // torus whose tube is 1e-3 of its ring radius.
  {
    MeshScene cone{solid_cone(20.0f, 40.0f, 64, 32), zoomed({0, 0, 40}, 4.0)};
    out.push_back({"cone_apex", "the cone's apex: per-slice apex normals, triangles collapsing to one point",
                   std::nullopt, cone, {}});
    MeshScene torus{solid_torus(0.022f, 22.0f, 32, 64), zoomed({0, 22.011, 0}, 0.2)};
    out.push_back({"thin_torus", "a torus with minor radius 0.022 (1e-3 of the major): sliver triangles",
                   std::nullopt, torus, {}});
  }
  return out;
}

namespace {

// A parameter's range as the model documents it (docs/hard-cases.md, docs/tolerances.md):
// the lobe parameters as the hard cases' lobe_map runs them. nullopt: none documented.
std::optional<std::pair<double, double>> documented_range(const std::string& model, const std::string& param) {
  if (auto lobe = lobe_range(model); lobe && lobe->param == param)
    return std::pair{std::min(lobe->broad, lobe->sharp), std::max(lobe->broad, lobe->sharp)};
  return std::nullopt;
}

std::string short_number(double v) { return fmt::format("{:.3g}", v); }

}  // namespace

std::vector<Scenario> user_scenarios(const Case& c, const UserCaseTraits& traits) {
  std::vector<Scenario> out;
  for (Scenario& s : scenarios_for(c.model, 0)) {
    // Mesh scenes are the library's; the lobe map needs a model's lobe parameter, drawn by rows.
    if (!s.slice || s.slice->layout == NormalLayout::half_angle) continue;
    const bool point_scenario = s.name == "light_near" || s.name == "light_on_surface";
    if (point_scenario) continue;   // added below for any point-light shader
    out.push_back(std::move(s));
    if (out.back().name == "sphere_coincident") {
      SliceSpec at_eye = sphere(kView);
      at_eye.light_at_eye = true;
      out.push_back({"light_at_eye", "the light at the eye: L = V, and a point light at the eye position", at_eye,
                     std::nullopt, {}});
    }
  }
  if (traits.point_light) {
    SliceSpec near{.layout = NormalLayout::plane, .plane_normal = glm::dvec3(0, 1, 0), .light_height = 1e-6};
    near.to_eye = kView;
    out.push_back({"light_near", "point light 1e-6 above the surface: distance -> 0, 1/d and 1/d^2 large", near,
                   std::nullopt, {}});
    SliceSpec on = near;
    on.light_height = 0;
    out.push_back({"light_on_surface", "point light on the surface: d = 0 at the centre pixel (L undefined there)", on,
                   std::nullopt, {}});
  }
  // Every scalar parameter a binding reads, at both ends of its range.
  std::set<std::string> bound;
  for (const auto& [language, table] : c.bindings)
    for (const auto& [uniform, binding] : table)
      for (const BindingSource& source : binding.sources)
        if (!source.name.empty()) bound.insert(source.name);
  for (const auto& [name, value] : c.params) {
    if (value.size() != 1 || !bound.contains(name)) continue;
    double low = 0, high = 0;
    std::string why;
    if (auto range = documented_range(c.model, name)) {
      std::tie(low, high) = *range;
      why = fmt::format("{}'s documented range {} .. {}", c.model, short_number(low), short_number(high));
    } else if (value[0] != 0) {
      low = 1e-3 * value[0];
      high = 1e3 * value[0];
      why = fmt::format("no range declared: 1e-3 .. 1e3 x the case's {}", short_number(value[0]));
    } else {
      continue;   // 0 has no scale to go around
    }
    for (const auto& [suffix, v] : {std::pair{"tiny", low}, {"huge", high}})
      out.push_back({fmt::format("{}_{}", name, suffix),
                     fmt::format("every normal, L perpendicular to V, {} = {} ({})", name, short_number(v), why),
                     sphere(kPerpendicular), std::nullopt, {{name, {v}}}});
  }
  if (traits.reads_tangent) {
    SliceSpec zero = sphere(kPerpendicular);
    zero.tangents = TangentLayout::zero;
    out.push_back({"tangent_zero", "every normal, L perpendicular to V, tangent attribute (0, 0, 0)", zero,
                   std::nullopt, {}});
    SliceSpec parallel = sphere(kPerpendicular);
    parallel.tangents = TangentLayout::parallel;
    out.push_back({"tangent_parallel", "every normal, L perpendicular to V, tangent attribute = N", parallel,
                   std::nullopt, {}});
  }
  return out;
}

std::vector<std::string> scenario_names() {
  return {"sphere_perpendicular", "sphere_opposite", "sphere_coincident", "long_normals", "sphere_sharp",
          "lobe_sharp",           "lobe_map",        "light_near",        "light_on_surface", "cone_apex",
          "thin_torus"};
}

}  // namespace shaderbed::hard
