// Every model against an independent 50-digit evaluation of docs/models.md (Oracle.h),
// over random configurations and hard ones: near the peak of sharp lobes, grazing light
// and view, L + V nearly zero, point lights at extreme distances, tiny and huge vector
// lengths. Prints the worst errors per set and model:
//   build/bin/test_reference --gtest_filter='Oracle.*'
//
// The criterion, per colour channel, with r the oracle's value and c the model's:
//   |c - r| <= 1e-12 |r| + 8 u(r) + 1e-290,
// where u(r) is how far r itself moves when every double the model is given (positions,
// normal, tangent, lights, or evaluate()'s L, V, N, T, distance) is moved by up to 2 ulps
// (the largest of 4 random such moves): the value's own uncertainty as a function of
// double inputs. Where a configuration is well conditioned u(r) is far below 1e-12 |r|
// and the criterion is 1e-12 relative. Where it is not (a dot product through 0 at a
// grazing angle, the direction of L + V when L is nearly -V, the tail of a 1e-6-wide
// lobe) no double evaluation can do better than its inputs allow: a model that rounds
// about as often as it has steps (normalise V, L + V, normalise H, build a frame, take
// dots: ~8) stays within 8 u(r), while a formula that cancels (1 - N·H, acos near 1) is
// off by 1/gamma times more, so the test still sees it.
// 1e-290, the absolute floor: near the bottom of double's range the result and its
// factors are subnormal and carry fewer than 40 bits. A value beyond the largest double
// must come out infinite.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <functional>
#include <map>
#include <random>
#include <vector>

#include <glm/ext/matrix_transform.hpp>

#include "ModelTestSupport.h"
#include "Oracle.h"
#include "reference/SceneLighting.h"

namespace reference {
namespace {

using namespace testing;
using oracle::Real;

constexpr double relative_tolerance = 1e-12;
constexpr double value_floor = 1e-290;
constexpr int perturbations = 4;
constexpr double uncertainty_factor = 8;

// One configuration as the model sees it, or as evaluate() is called.
struct Probe {
  std::string model;
  Params params;  // complete (defaults merged)
  std::optional<Configuration> configuration;  // through evaluate(), else point + lighting
  SurfacePoint point{};
  ObjectSpaceLighting lighting{};
  std::string label;
};

double nudge(double x, int ulps) {
  for (; ulps > 0; --ulps) x = std::nextafter(x, HUGE_VAL);
  for (; ulps < 0; ++ulps) x = std::nextafter(x, -HUGE_VAL);
  return x;
}

glm::dvec3 nudge(const glm::dvec3& v, std::mt19937_64& random) {
  std::uniform_int_distribution<int> ulps(-2, 2);
  return {nudge(v.x, ulps(random)), nudge(v.y, ulps(random)), nudge(v.z, ulps(random))};
}

bool is_spot_light(const std::string& model) { return model == "spot" || model == "warn"; }

std::optional<oracle::Colour> exact_value(const Probe& probe) {
  if (probe.configuration)
    return oracle::evaluate(probe.model, probe.params, oracle::exact(*probe.configuration, is_spot_light(probe.model)));
  return oracle::evaluate(probe.model, probe.params, oracle::exact(probe.point, probe.lighting));
}

Probe nudged(const Probe& probe, std::mt19937_64& random) {
  Probe moved = probe;
  if (moved.configuration) {
    Configuration& c = *moved.configuration;
    c.to_light = nudge(c.to_light, random);
    c.to_eye = nudge(c.to_eye, random);
    c.normal = nudge(c.normal, random);
    c.tangent = nudge(c.tangent, random);
    c.distance = nudge(c.distance, std::uniform_int_distribution<int>(-2, 2)(random));
    if (c.spot_axis) c.spot_axis = nudge(*c.spot_axis, random);
  } else {
    moved.point.position = nudge(moved.point.position, random);
    moved.point.normal = nudge(moved.point.normal, random);
    moved.point.tangent = nudge(moved.point.tangent, random);
    moved.lighting.light_direction = nudge(moved.lighting.light_direction, random);
    moved.lighting.light_position = nudge(moved.lighting.light_position, random);
    moved.lighting.eye_position = nudge(moved.lighting.eye_position, random);
  }
  return moved;
}

std::optional<glm::dvec3> model_value(const Probe& probe) {
  if (probe.configuration) {
    const auto colour = evaluate(probe.model, probe.params, *probe.configuration);
    EXPECT_TRUE(colour) << probe.label << ": " << colour.error();
    return colour ? std::optional(*colour) : std::nullopt;
  }
  auto model = make_model(probe.model, probe.params);
  EXPECT_TRUE(model) << model.error();
  if (!model) return std::nullopt;
  return (*model)->shade(probe.point, probe.lighting);
}

// The worst of a set of probes, per model.
struct Tally {
  int count = 0, ill_conditioned = 0, failures = 0;
  double max_relative = 0;       // |c - r| / |r| over every finite r above the floor
  double max_relative_well = 0;  // the same where 4 u(r) <= 1e-13 |r|
  double max_share = 0;          // |c - r| / tolerance
};

using Report = std::map<std::string, Tally>;

void judge(const Probe& probe, Report& report, std::mt19937_64& random) {
  const std::optional<oracle::Colour> exact = exact_value(probe);
  if (!exact) return;  // undefined: d = 0
  const std::optional<glm::dvec3> value = model_value(probe);
  if (!value) return;
  std::array<Real, 3> spread{};
  for (int k = 0; k < perturbations; ++k) {
    const auto moved = exact_value(nudged(probe, random));
    if (!moved) {
      for (Real& s : spread) s = std::numeric_limits<Real>::infinity();
      continue;
    }
    for (int i = 0; i < 3; ++i) spread[i] = std::max(spread[i], Real(abs((*moved)[i] - (*exact)[i])));
  }
  Tally& tally = report[probe.model];
  ++tally.count;
  bool ill = false;
  for (int i = 0; i < 3; ++i) {
    const Real r = (*exact)[i], c = (*value)[i], magnitude = abs(r);
    if (magnitude > DBL_MAX) {
      const bool ok = std::isinf(double((*value)[i])) && (c > 0) == (r > 0);
      if (!ok) ++tally.failures;
      EXPECT_TRUE(ok) << probe.label << " channel " << i << ": exact " << r.str(6) << " beyond double, got " << c;
      continue;
    }
    const Real error = std::isfinite((*value)[i]) ? Real(abs(c - r)) : std::numeric_limits<Real>::infinity();
    const Real tolerance = relative_tolerance * magnitude + uncertainty_factor * spread[i] + value_floor;
    const bool well = uncertainty_factor * spread[i] <= 1e-13 * magnitude;
    ill = ill || !well;
    if (magnitude > value_floor) {
      const double relative = double(error / magnitude);
      tally.max_relative = std::max(tally.max_relative, relative);
      if (well) tally.max_relative_well = std::max(tally.max_relative_well, relative);
    }
    tally.max_share = std::max(tally.max_share, double(error / tolerance));
    if (error > tolerance) {
      if (++tally.failures <= 3)
        ADD_FAILURE() << probe.label << " channel " << i << ": model " << c << ", exact " << r.str(17)
                      << ", error " << double(error) << " > tolerance " << double(tolerance)
                      << " (input uncertainty " << double(spread[i]) << ")";
    }
  }
  if (ill) ++tally.ill_conditioned;
}

void print(const std::string& set, const Report& report) {
  std::printf("%-22s %-17s %6s %6s %12s %12s %10s %5s\n", "set", "model", "probes", "ill", "max rel", "rel (well)",
              "of tol", "fail");
  for (const auto& [model, t] : report)
    std::printf("%-22s %-17s %6d %6d %12.3g %12.3g %10.3g %5d\n", set.c_str(), model.c_str(), t.count,
                t.ill_conditioned, t.max_relative, t.max_relative_well, t.max_share, t.failures);
  std::fflush(stdout);
}

Params with_defaults(const std::string& model, const Params& overrides = {}) {
  Params params = *default_params(model);
  for (const auto& [name, values] : overrides) params[name] = values;
  return params;
}

// ---- configurations ------------------------------------------------------------------------

glm::dvec3 random_direction(std::mt19937_64& random) {
  std::normal_distribution<double> gauss;
  return glm::normalize(glm::dvec3(gauss(random), gauss(random), gauss(random)));
}

double log_uniform(std::mt19937_64& random, double lo, double hi) {
  return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(random));
}

std::vector<double> random_colour(std::mt19937_64& random) {
  std::uniform_real_distribution<double> u(0.05, 1.0);
  return {u(random), u(random), u(random)};
}

Params random_params(const std::string& model, std::mt19937_64& random) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Params p = with_defaults(model);
  for (auto& [name, values] : p) {
    if (name == "diffuse" || name == "specular" || name == "ambient") values = random_colour(random);
    else if (name == "light_color") values = {10 * u(random), 10 * u(random), 10 * u(random)};
    else if (name == "power") values = {log_uniform(random, 1, 300)};
    else if (name == "minnaert_power") values = {2 * u(random)};
    else if (name == "roughness_sq") values = {u(random)};
    else if (name == "roughness" || name == "slope_m") values = {log_uniform(random, 0.02, 1)};
    else if (name == "roughness_xy") values = {log_uniform(random, 0.02, 1), log_uniform(random, 0.02, 1)};
    else if (name == "gaussian_c" || name == "fresnel_r0") values = {u(random)};
    else if (name == "attenuation") values = {0.01 * u(random), 0.1 * u(random), u(random)};
    else if (name == "cos_umbra") values = {0.8 + 0.2 * u(random)};
    else if (name == "falloff") values = {0.5 + 3 * u(random)};
    else if (name == "warn_exponent") values = {1 + 40 * u(random)};
  }
  if (p.contains("cos_penumbra")) p["cos_penumbra"] = {p["cos_umbra"][0] - 0.3 * u(random)};
  return p;
}

// L and V symmetric about H, H at angle gamma from N = +z (azimuth phi), L and V each
// theta from H.
std::pair<glm::dvec3, glm::dvec3> about_half_vector(double gamma, double phi, double theta, double roll) {
  const glm::dvec3 h(std::sin(gamma) * std::cos(phi), std::sin(gamma) * std::sin(phi), std::cos(gamma));
  const glm::dvec3 a = glm::normalize(glm::cross(h, glm::dvec3(std::cos(roll), std::sin(roll), 0.3)));
  const glm::dvec3 b = glm::cross(a, h);
  return {h * std::cos(theta) + b * std::sin(theta), h * std::cos(theta) - b * std::sin(theta)};
}

Probe directional(const std::string& model, const Params& params, const glm::dvec3& L, const glm::dvec3& V,
                  const glm::dvec3& N, const glm::dvec3& T, const std::string& label) {
  Probe probe{model, params, std::nullopt, {}, {}, label};
  probe.point = {glm::dvec3(0.0), N, T, glm::dvec2(0.0)};
  probe.lighting = {L, 50.0 * L, V};
  return probe;
}

const std::vector<std::string> oracle_models{"lambert",  "phong",    "blinn_phong", "schlick",
                                                  "minnaert", "oren_nayar", "ward_iso",  "ward_aniso",
                                                  "cook_torrance"};
const std::vector<std::string> point_models{"point_attenuated", "spot", "warn"};

// ---- the sets ------------------------------------------------------------------------------

TEST(Oracle, RandomConfigurations) {
  std::mt19937_64 random(13);
  std::uniform_real_distribution<double> u(-50, 50);
  Report report;
  for (const std::string& model : model_names()) {
    for (int i = 0; i < 300; ++i) {
      const Params params = i < 20 ? with_defaults(model) : random_params(model, random);
      Probe probe{model, params, std::nullopt, {}, {}, model + " random " + std::to_string(i)};
      const glm::dvec3 position(u(random), u(random), u(random));
      const glm::dvec3 normal = random_direction(random);
      probe.point = {position, normal, random_direction(random) * (0.5 + std::abs(u(random))), glm::dvec2(0.0)};
      probe.lighting = {random_direction(random), position + normal * 30.0 + glm::dvec3(u(random), u(random), u(random)),
                        position + random_direction(random) * 120.0};
      if (model == "spot" || model == "warn")  // aim the spot at the point, give or take the cone
        probe.lighting.light_direction =
            glm::normalize(probe.lighting.light_position - position + 10.0 * random_direction(random));
      judge(probe, report, random);
      // The same through evaluate(): directions of any length.
      Configuration configuration{random_direction(random) * 3.0, random_direction(random) * 0.2,
                                  random_direction(random), random_direction(random), 1 + std::abs(u(random)),
                                  std::nullopt};
      configuration.normal = glm::normalize(configuration.normal + configuration.to_light * 0.6);
      judge({model, params, configuration, {}, {}, model + " random evaluate " + std::to_string(i)}, report, random);
    }
  }
  print("random", report);
}

TEST(Oracle, NearThePeakOfSharpLobes) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> u(0, 1);
  Report report;
  const std::vector<double> widths{1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
  const std::vector<double> multiples{0, 0.1, 0.5, 1, 2, 3, 5, 10, 20};
  for (double s : widths) {
    for (double k : multiples) {
      for (int rep = 0; rep < 3; ++rep) {
        const double phi = 6.28 * u(random), theta = 0.05 + 1.2 * u(random), roll = 6.28 * u(random);
        const glm::dvec3 T = glm::normalize(glm::dvec3(std::cos(roll), std::sin(roll), 0.2 * u(random) - 0.1));
        const std::string where = " s=" + std::to_string(s) + " k=" + std::to_string(k);
        const auto [L0, V0] = about_half_vector(k * s, phi, theta, roll);
        // rep 0 in the axis-aligned frame (N = +z), the others rotated as a whole, so the
        // dots sum terms of mixed sign.
        const glm::dmat3 turn =
            rep == 0 ? glm::dmat3(1.0) : glm::dmat3(glm::rotate(glm::dmat4(1.0), 6.28 * u(random), random_direction(random)));
        const glm::dvec3 L = turn * L0, V = turn * V0, N = turn * z_axis, TT = turn * T;
        const auto add = [&](const std::string& model, const Params& overrides) {
          judge(directional(model, with_defaults(model, overrides), L, V, N, TT, model + where), report, random);
        };
        add("ward_iso", {{"roughness", {s}}});
        add("ward_aniso", {{"roughness_xy", {s, s}}});
        add("ward_aniso", {{"roughness_xy", {0.9, s}}});
        add("ward_aniso", {{"roughness_xy", {s, 0.3}}});
        add("cook_torrance", {{"slope_m", {s}}});
        add("cook_torrance", {{"slope_m", {s}}, {"fresnel_r0", {0}}});
        // The power models: a lobe of width 1/sqrt(n).
        const double n = 1 / (s * s);
        const auto [Lp, Vp] = about_half_vector(k * s, phi, theta, roll);
        judge(directional("blinn_phong", with_defaults("blinn_phong", {{"power", {n}}}), turn * Lp, turn * Vp, N, TT,
                          "blinn_phong" + where),
              report, random);
        // Phong and Schlick: V at k s from the mirror direction R of L.
        const glm::dvec3 L2 = about_half_vector(0, 0, theta, roll).first;
        const glm::dvec3 R = glm::dvec3(-L2.x, -L2.y, L2.z);
        const glm::dvec3 V2 = glm::normalize(R + k * s * glm::normalize(glm::cross(R, glm::dvec3(std::cos(phi), std::sin(phi), 0))));
        for (const std::string model : {"phong", "schlick"})
          judge(directional(model, with_defaults(model, {{"power", {n}}}), turn * L2, turn * V2, N, TT, model + where), report,
                random);
      }
    }
  }
  print("near the peak", report);
}

TEST(Oracle, GrazingLightAndView) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> u(0, 1);
  Report report;
  for (double e : {1e-2, 1e-4, 1e-6, 1e-9, 1e-12, 1e-15, 1e-200, -1e-9}) {
    for (int rep = 0; rep < 3; ++rep) {
      const double phi = 6.28 * u(random);
      const glm::dvec3 grazing(std::cos(e) * std::cos(phi), std::cos(e) * std::sin(phi), std::sin(e));
      glm::dvec3 other = random_direction(random);
      other.z = std::abs(other.z) + 0.1;
      other = glm::normalize(other);
      const glm::dvec3 T = random_direction(random);
      for (const std::string& model : oracle_models) {
        for (const bool light_grazes : {true, false}) {
          const glm::dvec3 L = light_grazes ? grazing : other, V = light_grazes ? other : grazing;
          judge(directional(model, with_defaults(model), L, V, z_axis, T,
                            model + " grazing e=" + std::to_string(e) + (light_grazes ? " L" : " V")),
                report, random);
        }
      }
      for (const std::string& model : point_models) {
        Probe probe = directional(model, with_defaults(model), -grazing, other, z_axis, T, model + " grazing");
        probe.lighting.light_position = 20.0 * grazing;
        judge(probe, report, random);
      }
    }
  }
  print("grazing", report);
}

TEST(Oracle, LightNearlyOppositeTheEye) {
  std::mt19937_64 random(5);
  Report report;
  for (double e : {1e-2, 1e-5, 1e-8, 1e-10, 1e-12, 1e-15}) {
    for (int rep = 0; rep < 4; ++rep) {
      const glm::dvec3 L = random_direction(random);
      const glm::dvec3 V = glm::normalize(-L + e * random_direction(random));
      for (const std::string& model : oracle_models)
        judge(directional(model, with_defaults(model), L, V, z_axis, x_axis, model + " opposite e=" + std::to_string(e)),
              report, random);
      // Symmetric about N: the sum lies along N exactly, H = N.
      const glm::dvec3 A(std::cos(e), 0, std::sin(e)), B(-std::cos(e), 0, std::sin(e));
      judge(directional("blinn_phong", with_defaults("blinn_phong"), A, B, z_axis, x_axis, "blinn_phong symmetric"),
            report, random);
    }
  }
  print("L nearly -V", report);
}

TEST(Oracle, PointLightsAtExtremeDistances) {
  std::mt19937_64 random(3);
  Report report;
  for (double d : {1e-305, 1e-300, 1e-250, 1e-200, 1e-163, 1e-160, 1e-155, 1e-100, 1e-5, 1.0, 1e5, 1e100, 1e154,
                   1.4e154, 1e160, 1e200, 1e250, 1e300, 1e305}) {
    for (const Params& attenuation : {Params{}, Params{{"attenuation", {0.001, 0.04, 0.5}}},
                                      Params{{"attenuation", {1e-3, 0, 0}}}}) {
      for (const std::string& model : point_models) {
        if (model == "warn" && !attenuation.empty()) continue;
        const Params params = with_defaults(model, attenuation);
        glm::dvec3 Lp = random_direction(random);
        Lp.z = std::abs(Lp.z) + 0.2;
        Lp = glm::normalize(Lp);
        const std::string label = model + " d=" + std::to_string(d);
        // The spot shining at the point from along Lp (inside the umbra), and off-axis.
        for (const double off : {0.0, 0.3}) {
          Probe probe = directional(model, params, glm::normalize(Lp + off * x_axis), z_axis, z_axis, x_axis, label);
          probe.lighting.light_position = d * Lp;
          judge(probe, report, random);
          Configuration configuration{Lp, z_axis, z_axis, x_axis, d, -glm::normalize(Lp + off * x_axis)};
          judge({model, params, configuration, {}, {}, label + " evaluate"}, report, random);
        }
        // A directional-light model lit by the point light (SceneLight::point).
        if (model == "point_attenuated") {
          auto lit = with_scene_lighting(*make_model("lambert", with_defaults("lambert")), "lambert",
                                         SceneLight::point, glm::dvec3(0.0));
          ASSERT_TRUE(lit);
          const glm::dvec3 colour = (*lit)->shade({glm::dvec3(0.0), z_axis, x_axis, {}},
                                                  {z_axis, d * Lp, z_axis});
          EXPECT_NEAR(colour.r, Lp.z, 1e-15) << "lambert lit by a point light at d = " << d;
        }
      }
    }
  }
  print("extreme distances", report);
}

TEST(Oracle, TinyAndHugeVectorLengths) {
  std::mt19937_64 random(17);
  Report report;
  for (double scale : {1e-320, 1e-300, 1e-200, 1e-160, 1e-100, 1e100, 1e160, 1e200, 1e300}) {
    for (int rep = 0; rep < 3; ++rep) {
      glm::dvec3 L = random_direction(random), V = random_direction(random);
      L.z = std::abs(L.z) + 0.3;
      V.z = std::abs(V.z) + 0.3;
      const glm::dvec3 N = glm::normalize(glm::dvec3(0.1, -0.2, 1)), T = random_direction(random);
      for (const std::string& model : model_names()) {
        const std::string label = model + " scale=" + std::to_string(scale);
        // evaluate(): every direction scaled (a finite non-zero vector has a direction).
        Configuration configuration{L * scale, V * scale, N * scale, T * scale, 20, std::nullopt};
        judge({model, with_defaults(model), configuration, {}, {}, label + " evaluate"}, report, random);
        // The model: the eye and the point light at that distance, the tangent that long.
        Probe probe = directional(model, with_defaults(model), glm::normalize(L), glm::dvec3(0.0), N, T * scale, label);
        probe.lighting.eye_position = glm::normalize(V) * scale;
        probe.lighting.light_position = glm::normalize(L) * 30.0;
        judge(probe, report, random);
      }
    }
  }
  // Tangents nearly parallel to N still define ward_aniso's frame.
  for (double e : {1e-3, 1e-8, 1e-12, 1e-15}) {
    const glm::dvec3 T = z_axis + e * glm::dvec3(0.6, 0.8, 0);
    judge(directional("ward_aniso", with_defaults("ward_aniso"), direction(40, 10), direction(35, 200), z_axis, T,
                      "ward_aniso near-parallel tangent"),
          report, random);
  }
  print("vector lengths", report);
}

}  // namespace
}  // namespace reference
