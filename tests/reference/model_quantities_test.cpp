// The models' named intermediate quantities (LightingModel::quantities, model_quantities):
// at every covered pixel of a small sphere, "colour" is render()'s pixel bit for bit, the
// dot products are the dots of the reported vectors, each model's terms recombine into its
// colour by docs/models.md's equation, and the world-space vectors are the object-space
// ones carried by the world matrix.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/ext/matrix_transform.hpp>
#include <map>
#include <numbers>
#include <optional>

#include "UvSphere.h"
#include "reference/ModelQuantities.h"
#include "reference/Reference.h"

namespace reference::model_quantities_test {
namespace {

constexpr int kSize = 40;

// A radius-25 sphere (a unit mesh under a rotated, uniformly scaled world matrix, so the
// world-space quantities differ from the object-space ones) seen by the book's camera.
Scene quantities_sphere() {
  Scene scene;
  scene.mesh = test::uv_sphere(24, 16);
  scene.world = glm::rotate(glm::dmat4(1.0), 0.5, glm::dvec3(0.3, 1.0, 0.2)) * glm::scale(glm::dmat4(1.0), glm::dvec3(25.0));
  scene.width = scene.height = kSize;
  return scene;
}

// One pixel's quantities by name (the first of a name, as a matcher would read them).
class Quantities {
 public:
  explicit Quantities(const std::vector<NamedQuantity>& list) {
    for (const NamedQuantity& quantity : list) by_name_.try_emplace(quantity.name, quantity.values);
  }
  bool has(const std::string& name) const { return by_name_.contains(name); }
  double scalar(const std::string& name) const {
    const auto found = by_name_.find(name);
    EXPECT_TRUE(found != by_name_.end() && found->second.size() == 1) << "no scalar " << name;
    return found != by_name_.end() && found->second.size() == 1 ? found->second[0] : NAN;
  }
  glm::dvec3 vector(const std::string& name) const {
    const auto found = by_name_.find(name);
    EXPECT_TRUE(found != by_name_.end() && found->second.size() == 3) << "no vector " << name;
    if (found == by_name_.end() || found->second.size() != 3) return glm::dvec3(NAN);
    return {found->second[0], found->second[1], found->second[2]};
  }

 private:
  std::map<std::string, std::vector<double>> by_name_;
};

std::vector<std::pair<int, int>> all_pixels(const Scene& scene) {
  std::vector<std::pair<int, int>> pixels;
  for (int y = 0; y < scene.height; ++y)
    for (int x = 0; x < scene.width; ++x) pixels.emplace_back(x, y);
  return pixels;
}

Params defaults_of(const std::string& model) {
  auto params = default_params(model);
  EXPECT_TRUE(params) << params.error();
  return params ? *params : Params{};
}

void expect_close(double actual, double expected, const std::string& what, double relative = 1e-12) {
  EXPECT_NEAR(actual, expected, relative * (1.0 + std::abs(expected))) << what;
}

void expect_close(const glm::dvec3& actual, const glm::dvec3& expected, const std::string& what,
                  double relative = 1e-12) {
  for (int k = 0; k < 3; ++k) expect_close(actual[k], expected[k], what + "[" + std::to_string(k) + "]", relative);
}

// Runs `check` on every covered pixel's quantities, after checking "colour" against
// render()'s pixel bit for bit and that an uncovered pixel has none; returns how many
// pixels were covered.
int for_each_pixel(const Scene& scene, const std::string& model, const Params& params,
                   const std::function<void(const Quantities&)>& check, const Perturbation& perturbation = {}) {
  const auto image = render(scene, model, Mode::per_pixel, params, perturbation);
  EXPECT_TRUE(image) << image.error();
  const std::vector<std::pair<int, int>> pixels = all_pixels(scene);
  const auto quantities = model_quantities(scene, model, params, pixels, perturbation);
  EXPECT_TRUE(quantities) << quantities.error();
  if (!image || !quantities) return 0;
  int covered = 0;
  for (size_t pixel = 0; pixel < pixels.size(); ++pixel) {
    const std::vector<NamedQuantity>& list = (*quantities)[pixel];
    if (!image->coverage[pixel]) {
      EXPECT_TRUE(list.empty()) << model << ": uncovered pixel " << pixel << " has quantities";
      continue;
    }
    ++covered;
    EXPECT_FALSE(list.empty());
    if (list.empty()) continue;
    EXPECT_EQ(list.back().name, "colour") << model;
    const Quantities named(list);
    const glm::dvec3 colour = named.vector("colour");
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(colour[k], image->rgba[pixel * 4 + k]) << model << " pixel " << pixel << " channel " << k;
    check(named);
    if (::testing::Test::HasFailure()) return covered;  // one pixel's failures say enough
  }
  return covered;
}

// A dot product the model reports (raw, and clamped as sat(...)) against the dot of the
// vectors it reports: bit for bit where the model takes that dot (N·L, N·V, N·Lp, Lp·L),
// else to rounding (R·V and N·H near the peak come from the angle between the vectors).
void expect_dot(const Quantities& q, const std::string& a, const std::string& b) {
  const std::string name = a + "·" + b;
  if (!q.has(name) || !q.has(a) || !q.has(b)) return;
  const double dot = glm::dot(q.vector(a), q.vector(b));
  if ((a == "N" && (b == "L" || b == "V" || b == "Lp")) || a == "Lp") {
    EXPECT_EQ(q.scalar(name), dot) << name;
  } else {
    EXPECT_NEAR(q.scalar(name), dot, 1e-14) << name;
  }
  if (q.has("sat(" + name + ")")) {
    EXPECT_EQ(q.scalar("sat(" + name + ")"), std::max(0.0, q.scalar(name))) << name;
  }
}

// The checks every model's quantities pass.
void expect_common(const Quantities& q) {
  for (const auto& [a, b] : {std::pair{"N", "L"}, {"N", "V"}, {"N", "Lp"}, {"R", "V"}, {"N", "H"}, {"Lp", "L"}})
    expect_dot(q, a, b);
  for (const char* unit : {"N", "L", "V", "H", "R", "Lp", "X", "Y"})
    if (q.has(unit)) expect_close(glm::length(q.vector(unit)), 1.0, std::string(unit) + " is unit");
  // The pixel's inputs and the world versions of its vectors.
  const glm::dvec3 p = q.vector("P");
  expect_close(q.vector("N"), glm::normalize(q.vector("N interpolated")), "N = normalize(N interpolated)");
  if (q.has("V")) expect_close(q.vector("V"), glm::normalize(q.vector("eye_position") - p), "V");
  if (q.has("light_position−P")) {
    const glm::dvec3 to_light = q.vector("light_position−P");
    expect_close(to_light, q.vector("light_position") - p, "light_position−P");
    expect_close(q.scalar("d"), glm::length(to_light), "d");
    if (q.has("Lp")) expect_close(q.vector("Lp"), to_light / glm::length(to_light), "Lp");
  }
  const Camera camera;
  const Lights lights;
  expect_close(q.vector("eye_position world"), camera.eye, "eye_position world");
  expect_close(q.vector("light_position world"), lights.position, "light_position world");
  expect_close(q.vector("light_vector world"), lights.direction, "light_vector world");
  if (q.has("V")) expect_close(q.vector("V world"), glm::normalize(camera.eye - q.vector("P world")), "V world");
  // A similarity world matrix keeps the dot products.
  if (q.has("N·L")) expect_close(glm::dot(q.vector("N world"), q.vector("L world")), q.scalar("N·L"), "N·L world");
}

using ModelCheck = std::function<void(const Quantities&, const Params&)>;

glm::dvec3 colour_param(const Params& params, const std::string& name) {
  const std::vector<double>& v = params.at(name);
  return {v[0], v[1], v[2]};
}

// Each model's terms recombine into its colour by docs/models.md's equation.
const std::map<std::string, ModelCheck>& model_checks() {
  static const std::map<std::string, ModelCheck> checks{
      {"ambient",
       [](const Quantities& q, const Params& p) { EXPECT_EQ(q.vector("colour"), colour_param(p, "ambient")); }},
      {"lambert",
       [](const Quantities& q, const Params& p) {
         EXPECT_EQ(q.vector("colour"), colour_param(p, "diffuse") * q.scalar("sat(N·L)"));
       }},
      {"phong",
       [](const Quantities& q, const Params& p) {
         const glm::dvec3 n = q.vector("N"), l = q.vector("L");
         expect_close(q.vector("R"), glm::normalize(2.0 * n * glm::dot(n, l) - l), "R");
         expect_close(q.scalar("sat(R·V)^power"), std::pow(q.scalar("sat(R·V)"), p.at("power")[0]), "highlight");
         EXPECT_EQ(q.vector("specular"), colour_param(p, "specular") * q.scalar("sat(R·V)^power"));
         EXPECT_EQ(q.vector("diffuse"), colour_param(p, "diffuse") * q.scalar("sat(N·L)"));
         EXPECT_EQ(q.vector("colour"), q.vector("diffuse") + q.vector("specular"));
       }},
      {"blinn_phong",
       [](const Quantities& q, const Params& p) {
         expect_close(q.vector("H"), glm::normalize(q.vector("L") + q.vector("V")), "H");
         expect_close(q.scalar("sat(N·H)^power"), std::pow(q.scalar("sat(N·H)"), p.at("power")[0]), "highlight");
         EXPECT_EQ(q.vector("specular"), colour_param(p, "specular") * q.scalar("sat(N·H)^power"));
         EXPECT_EQ(q.vector("colour"), q.vector("diffuse") + q.vector("specular"));
       }},
      {"schlick",
       [](const Quantities& q, const Params& p) {
         const double t = q.scalar("t"), n = p.at("power")[0];
         EXPECT_EQ(t, std::max(0.0, q.scalar("R·V")));
         expect_close(q.scalar("t / (power − (power − 1) t)"), t / (n - (n - 1) * t), "highlight");
         EXPECT_EQ(q.vector("colour"), q.vector("diffuse") + q.vector("specular"));
       }},
      {"minnaert",
       [](const Quantities& q, const Params& p) {
         const double nl = q.scalar("sat(N·L)"), nv = q.scalar("sat(N·V)");
         expect_close(q.vector("colour"),
                      colour_param(p, "diffuse") * (std::pow(nv * nl, p.at("minnaert_power")[0]) * nl), "colour");
       }},
      {"oren_nayar",
       [](const Quantities& q, const Params& p) {
         const double s = p.at("roughness_sq")[0];
         expect_close(q.scalar("A"), 1 - 0.5 * s / (s + 0.33), "A");
         expect_close(q.scalar("B"), 0.45 * s / (s + 0.09), "B");
         if (q.scalar("N·L") <= 0) {
           EXPECT_EQ(q.vector("colour"), glm::dvec3(0.0));
           return;
         }
         expect_close(q.scalar("sin α"), std::sin(q.scalar("α")), "sin α", 1e-9);
         expect_close(q.scalar("tan β"), std::tan(q.scalar("β")), "tan β", 1e-9);
         const double factor = q.scalar("A") + q.scalar("B") * q.scalar("cosC") * q.scalar("sin α") * q.scalar("tan β");
         expect_close(q.vector("colour"), colour_param(p, "diffuse") * (q.scalar("sat(N·L)") * factor), "colour");
       }},
      {"ward_iso",
       [](const Quantities& q, const Params& p) {
         const double sigma = p.at("roughness")[0];
         if (q.scalar("N·L") > 0 && q.scalar("N·V") > 0) {
           const double nh = q.scalar("N·H");
           const double tan2 = (1 - nh * nh) / (nh * nh);
           expect_close(q.scalar("tan²γ"), tan2, "tan²γ", 1e-9);
           const glm::dvec3 spec = colour_param(p, "specular") * std::exp(-tan2 / (sigma * sigma)) /
                                   (4 * std::numbers::pi * sigma * sigma) /
                                   std::sqrt(q.scalar("N·L") * q.scalar("N·V"));
           expect_close(q.vector("specular"), spec, "specular", 1e-9);
         } else {
           EXPECT_EQ(q.vector("specular"), glm::dvec3(0.0));
         }
         EXPECT_EQ(q.vector("colour"), (colour_param(p, "diffuse") + q.vector("specular")) * q.scalar("sat(N·L)"));
       }},
      {"ward_aniso",
       [](const Quantities& q, const Params& p) {
         const glm::dvec2 sigma(p.at("roughness_xy")[0], p.at("roughness_xy")[1]);
         if (q.scalar("N·L") > 0 && q.scalar("N·V") > 0) {
           const glm::dvec3 n = q.vector("N"), x = q.vector("X"), h = q.vector("H");
           expect_close(glm::dot(n, x), 0.0, "X ⟂ N");
           expect_close(q.vector("Y"), glm::cross(n, x), "Y");
           EXPECT_EQ(q.scalar("H·X"), glm::dot(h, x));
           const double hx = glm::dot(h, x) / sigma.x, hy = glm::dot(h, q.vector("Y")) / sigma.y;
           const glm::dvec3 spec = colour_param(p, "specular") / (4 * std::numbers::pi * sigma.x * sigma.y) /
                                   std::sqrt(q.scalar("N·L") * q.scalar("N·V")) *
                                   std::exp(-2 * (hx * hx + hy * hy) / (1 + glm::dot(n, h)));
           expect_close(q.vector("specular"), spec, "specular");
         }
         EXPECT_EQ(q.vector("colour"), (colour_param(p, "diffuse") + q.vector("specular")) * q.scalar("sat(N·L)"));
       }},
      {"cook_torrance",
       [](const Quantities& q, const Params& p) {
         const double nl = q.scalar("N·L"), nv = q.scalar("N·V");
         if (!(nl > 0 && nv > 0)) {
           EXPECT_EQ(q.vector("colour"), glm::dvec3(0.0));
           return;
         }
         const double c = p.at("gaussian_c")[0], m = p.at("slope_m")[0], r0 = p.at("fresnel_r0")[0];
         const double nh = q.scalar("sat(N·H)"), vh = q.scalar("V·H");
         expect_close(vh, glm::dot(q.vector("V"), q.vector("H")), "V·H");
         expect_close(q.scalar("a"), std::acos(nh), "a", 1e-7);  // acos near 1 keeps half the digits
         expect_close(q.scalar("D"), c * std::exp(-std::pow(q.scalar("a") / m, 2)), "D");
         expect_close(q.scalar("F"), r0 + (1 - r0) * std::pow(1 - vh, 5), "F", 1e-10);
         expect_close(q.scalar("G"), std::max(0.0, std::min({1.0, 2 * nh * nv / vh, 2 * nh * nl / vh})), "G");
         const double brdf = q.scalar("F") * q.scalar("D") * q.scalar("G") / (nl * nv);
         expect_close(q.vector("colour"), colour_param(p, "diffuse") * brdf, "colour = diffuse F D G/((N·L)(N·V))");
       }},
      {"point_attenuated",
       [](const Quantities& q, const Params& p) {
         const glm::dvec3 a = colour_param(p, "attenuation");
         const double d = q.scalar("d");
         expect_close(q.scalar("A d² + B d + C"), a.x * d * d + a.y * d + a.z, "denominator");
         expect_close(q.vector("colour"),
                      colour_param(p, "diffuse") * colour_param(p, "light_color") * q.scalar("sat(N·Lp)") *
                          q.scalar("attenuation"),
                      "colour");
       }},
      {"spot",
       [](const Quantities& q, const Params& p) {
         const double cos_theta = q.scalar("Lp·L"), umbra = p.at("cos_umbra")[0], penumbra = p.at("cos_penumbra")[0];
         const double expected_spot =
             cos_theta >= umbra ? 1.0
             : cos_theta <= penumbra
                 ? 0.0
                 : std::pow((cos_theta - penumbra) / (umbra - penumbra), p.at("falloff")[0]);
         expect_close(q.scalar("spot"), expected_spot, "spot");
         expect_close(q.vector("colour"),
                      colour_param(p, "diffuse") * colour_param(p, "light_color") * q.scalar("spot") *
                          q.scalar("sat(N·Lp)") * q.scalar("attenuation"),
                      "colour");
       }},
      {"warn",
       [](const Quantities& q, const Params& p) {
         const double d = q.scalar("d");
         expect_close(q.scalar("sat(Lp·L)^warn_exponent"),
                      std::pow(q.scalar("sat(Lp·L)"), p.at("warn_exponent")[0]), "cone");
         expect_close(q.vector("colour"),
                      colour_param(p, "diffuse") * colour_param(p, "light_color") *
                          q.scalar("sat(Lp·L)^warn_exponent") * q.scalar("sat(N·Lp)") / (d * d),
                      "colour", 1e-11);
       }},
  };
  return checks;
}

class ModelQuantities : public ::testing::TestWithParam<std::string> {};

TEST_P(ModelQuantities, ColourIsTheRenderedPixelAndTheTermsMakeIt) {
  const std::string& model = GetParam();
  const Params params = defaults_of(model);
  const auto check = model_checks().find(model);
  ASSERT_NE(check, model_checks().end()) << "no checks for model " << model;
  const int covered = for_each_pixel(quantities_sphere(), model, params, [&](const Quantities& q) {
    if (model != "ambient") expect_common(q);
    check->second(q, params);
  });
  EXPECT_GT(covered, 100);
}

TEST_P(ModelQuantities, SharpLobesAndHighPowersToo) {
  // The models' other branches: powers above the plain-pow limit, a sharp lobe.
  const std::string& model = GetParam();
  Params params = defaults_of(model);
  if (params.contains("power")) params["power"] = {1000};
  if (params.contains("slope_m")) params["slope_m"] = {0.05};
  if (params.contains("roughness")) params["roughness"] = {0.02};
  if (params.contains("falloff")) params["falloff"] = {3};
  for_each_pixel(quantities_sphere(), model, params, [&](const Quantities& q) {
    if (model != "ambient") expect_common(q);
    model_checks().at(model)(q, params);
  });
}

TEST_P(ModelQuantities, ColourIsTheRenderedPixelUnderEveryPerturbation) {
  const std::string& model = GetParam();
  const Params params = defaults_of(model);
  for (const Perturbation perturbation :
       {Perturbation{.negate_light = true}, Perturbation{.negate_eye = true}, Perturbation{.unnormalised_normal = true},
        Perturbation{.interpolated_light_eye = true}, Perturbation{.faceted_normal = true}}) {
    for_each_pixel(quantities_sphere(), model, params, [](const Quantities&) {}, perturbation);
  }
}

TEST_P(ModelQuantities, AmbientAndThePointLightAreReportedAsRenderAppliesThem) {
  const std::string& model = GetParam();
  const Params params = defaults_of(model);
  Scene scene = quantities_sphere();
  scene.ambient = {0.05, 0.1, 0.2};
  const bool point_lit = model != "ambient" && model != "point_attenuated" && model != "spot" && model != "warn";
  if (point_lit) scene.light = SceneLight::point;
  for_each_pixel(scene, model, params, [&](const Quantities& q) {
    EXPECT_EQ(q.vector("ambient_light"), scene.ambient);
    EXPECT_EQ(q.vector("colour"), q.vector("model colour") + q.vector("ambient_light"));
    if (point_lit) {
      // The directional-light model's L is the point light's.
      const glm::dvec3 to_light = q.vector("light_position−P");
      expect_close(q.vector("L"), to_light / glm::length(to_light), "L = normalize(light_position − P)");
      expect_dot(q, "N", "L");
    }
  });
}

INSTANTIATE_TEST_SUITE_P(Models, ModelQuantities, ::testing::ValuesIn(model_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(ModelQuantitiesCall, UncoveredPixelsAreEmptyAndBadInputsAreErrors) {
  const Scene scene = quantities_sphere();
  const std::vector<std::pair<int, int>> corner{{0, 0}, {kSize / 2, kSize / 2}};
  const auto quantities = model_quantities(scene, "phong", defaults_of("phong"), corner);
  ASSERT_TRUE(quantities) << quantities.error();
  ASSERT_EQ(quantities->size(), 2u);
  EXPECT_TRUE((*quantities)[0].empty());
  EXPECT_FALSE((*quantities)[1].empty());

  const std::vector<std::pair<int, int>> outside{{kSize, 0}};
  const auto out = model_quantities(scene, "phong", defaults_of("phong"), outside);
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().find("outside"), std::string::npos) << out.error();
  const auto unknown = model_quantities(scene, "no-such-model", {}, corner);
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().find("no-such-model"), std::string::npos);
}

TEST(ModelQuantitiesCall, ScalarsHaveOneValueVectorsThreeAndWorldVersionsFollow) {
  const Scene scene = quantities_sphere();
  const std::vector<std::pair<int, int>> centre{{kSize / 2, kSize / 2}};
  const auto quantities = model_quantities(scene, "cook_torrance", defaults_of("cook_torrance"), centre);
  ASSERT_TRUE(quantities) << quantities.error();
  const std::vector<NamedQuantity>& list = (*quantities)[0];
  for (size_t i = 0; i < list.size(); ++i) {
    ASSERT_TRUE(list[i].values.size() == 1 || list[i].values.size() == 3) << list[i].name;
    const bool world = list[i].name.ends_with(" world");
    if (world) {
      ASSERT_GT(i, 0u);
      EXPECT_EQ(list[i].name, list[i - 1].name + " world");
    }
  }
  const Quantities q(list);
  for (const char* name : {"N", "L", "V", "H", "L+V", "P", "N·L", "N·V", "N·H", "sat(N·H)", "V·H", "D", "F", "G",
                           "colour"})
    EXPECT_TRUE(q.has(name)) << name;
  EXPECT_FALSE(q.has("colour world"));
  expect_close(q.vector("P world"), glm::dvec3(scene.world * glm::dvec4(q.vector("P"), 1.0)), "P world");
  expect_close(glm::length(q.vector("P world")), 25.0, "on the radius-25 sphere", 1e-2);
  // A sum of directions keeps its length, as a world-space shader's L + V does.
  expect_close(q.vector("L+V world"), q.vector("L world") + q.vector("V world"), "L+V world");
  // A difference of positions scales with the world matrix.
  const auto point_lit = model_quantities(scene, "point_attenuated", defaults_of("point_attenuated"), centre);
  ASSERT_TRUE(point_lit) << point_lit.error();
  const Quantities p((*point_lit)[0]);
  expect_close(p.vector("light_position−P world"), Lights{}.position - p.vector("P world"), "light_position−P world");
}

}  // namespace
}  // namespace reference::model_quantities_test
