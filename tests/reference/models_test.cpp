// Lighting models at hand-computed (N, L, V) configurations, and their parameter errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "reference/ModelRegistry.h"

namespace reference {
namespace {

const Params phong_params{{"diffuse", {0.2, 0.3, 0.4}}, {"specular", {0.5, 0.6, 0.7}}, {"power", {7}}};
const glm::dvec3 up{0, 1, 0};

// Surface point at the origin with normal +y; the eye 10 units along `to_eye`.
glm::dvec3 shade(const std::string& model_name, const Params& params, const glm::dvec3& to_light,
                 const glm::dvec3& to_eye, const glm::dvec3& normal = up) {
  auto model = make_model(model_name, params);
  EXPECT_TRUE(model) << model.error();
  const SurfacePoint point{{0, 0, 0}, normal, {1, 0, 0}, {0, 0}};
  const ObjectSpaceLighting lighting{glm::normalize(to_light), {0, 50, 0}, 10.0 * glm::normalize(to_eye)};
  return (*model)->shade(point, lighting);
}

// Unit vector in the x-y plane at `degrees` from +y, toward +x.
glm::dvec3 from_normal(double degrees) { return {std::sin(glm::radians(degrees)), std::cos(glm::radians(degrees)), 0}; }

void expect_colour(const glm::dvec3& actual, const glm::dvec3& expected) {
  EXPECT_NEAR(actual.r, expected.r, 1e-12);
  EXPECT_NEAR(actual.g, expected.g, 1e-12);
  EXPECT_NEAR(actual.b, expected.b, 1e-12);
}

TEST(Models, AmbientIsItsColourEverywhere) {
  const Params params{{"ambient", {0.1, 0.2, 0.3, 1.0}}};
  expect_colour(shade("ambient", params, up, up), {0.1, 0.2, 0.3});
  expect_colour(shade("ambient", params, -up, -up), {0.1, 0.2, 0.3});
}

TEST(Models, LambertIsDiffuseTimesCosineClampedAtZero) {
  const Params params{{"diffuse", {0.8, 0.6, 0.4}}};
  expect_colour(shade("lambert", params, up, up), {0.8, 0.6, 0.4});
  expect_colour(shade("lambert", params, from_normal(60), up), {0.4, 0.3, 0.2});  // cos 60 = 1/2
  expect_colour(shade("lambert", params, from_normal(90), up), {0, 0, 0});
  expect_colour(shade("lambert", params, from_normal(120), up), {0, 0, 0});  // clamped, not -1/2
}

TEST(Models, PhongWithLightAndEyeAlongTheNormalIsDiffusePlusSpecular) {
  expect_colour(shade("phong", phong_params, up, up), {0.7, 0.9, 1.1});  // unclamped
}

TEST(Models, PhongAtSixtyDegrees) {
  // L at 60 degrees: N·L = 1/2, R at -60 degrees. Eye along N: R·V = cos 60 = 1/2.
  const double half_to_the_power = std::pow(0.5, 7);
  expect_colour(shade("phong", phong_params, from_normal(60), up),
                glm::dvec3(0.1, 0.15, 0.2) + half_to_the_power * glm::dvec3(0.5, 0.6, 0.7));
  // Eye along R: the full highlight.
  expect_colour(shade("phong", phong_params, from_normal(60), from_normal(-60)),
                glm::dvec3(0.1, 0.15, 0.2) + glm::dvec3(0.5, 0.6, 0.7));
  // Eye along L (120 degrees from R): R·V = -1/2, clamped to no highlight.
  expect_colour(shade("phong", phong_params, from_normal(60), from_normal(60)), {0.1, 0.15, 0.2});
}

TEST(Models, PhongSpecularIsNotGatedByTheDiffuseTerm) {
  // Light below the horizon (N·L = -1/2): no diffuse, but the eye along R = 2N(N·L) - L
  // still sees the full highlight, as in the book's shaders.
  const glm::dvec3 to_light = from_normal(120);
  const glm::dvec3 reflection = 2.0 * up * glm::dot(up, to_light) - to_light;
  expect_colour(shade("phong", phong_params, to_light, reflection), {0.5, 0.6, 0.7});
}

TEST(Models, PhongUsesTheEyePositionRelativeToThePoint) {
  auto model = make_model("phong", phong_params);
  ASSERT_TRUE(model);
  // Point at (5, 0, 0), eye at (5, 10, 0): V = +y even though the eye is not along +y
  // from the origin.
  const SurfacePoint point{{5, 0, 0}, up, {1, 0, 0}, {0, 0}};
  expect_colour((*model)->shade(point, {up, {0, 50, 0}, {5, 10, 0}}), {0.7, 0.9, 1.1});
}

TEST(Models, NamesAreRegisteredAndBuildableFromTheirDefaults) {
  const std::vector<std::string> names = model_names();
  for (const char* name : {"ambient", "lambert", "phong", "blinn_phong", "schlick", "minnaert", "oren_nayar",
                           "ward_iso", "ward_aniso", "cook_torrance", "point_attenuated", "spot", "warn"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  }
  EXPECT_EQ(names.size(), 13u);
  for (const std::string& name : names) {
    const auto defaults = default_params(name);
    ASSERT_TRUE(defaults) << name;
    EXPECT_TRUE(make_model(name, *defaults)) << name;
    // Every default is needed: dropping any one is a "missing parameter" error.
    for (const auto& [parameter, values] : *defaults) {
      Params without = *defaults;
      without.erase(parameter);
      const auto model = make_model(name, without);
      ASSERT_FALSE(model) << name << " without " << parameter;
      EXPECT_EQ(model.error(), name + ": missing parameter '" + parameter + "'");
    }
  }
}

TEST(Models, MissingParameterNamesTheModelAndTheParameter) {
  const auto missing_specular = make_model("phong", {{"diffuse", {1, 1, 1}}, {"power", {7}}});
  ASSERT_FALSE(missing_specular);
  EXPECT_EQ(missing_specular.error(), "phong: missing parameter 'specular'");

  const auto missing_all = make_model("phong", {});
  ASSERT_FALSE(missing_all);
  for (const char* name : {"'diffuse'", "'specular'", "'power'"}) {
    EXPECT_NE(missing_all.error().find(name), std::string::npos) << missing_all.error();
  }

  const auto lambert = make_model("lambert", {{"ambient", {1, 1, 1}}});
  ASSERT_FALSE(lambert);
  EXPECT_EQ(lambert.error(), "lambert: missing parameter 'diffuse'");
}

TEST(Models, MalformedParameterIsAnError) {
  const auto two_component_colour = make_model("lambert", {{"diffuse", {1, 1}}});
  ASSERT_FALSE(two_component_colour);
  EXPECT_NE(two_component_colour.error().find("lambert: parameter 'diffuse'"), std::string::npos);

  const auto vector_power = make_model("phong", {{"diffuse", {1, 1, 1}}, {"specular", {1, 1, 1}}, {"power", {7, 8}}});
  ASSERT_FALSE(vector_power);
  EXPECT_NE(vector_power.error().find("'power'"), std::string::npos);
}

TEST(Models, UnknownModelIsAnError) {
  const auto unknown = make_model("blinn-phong-typo", {});
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().find("unknown lighting model 'blinn-phong-typo'"), std::string::npos);
  EXPECT_NE(unknown.error().find("phong"), std::string::npos) << "lists the known models";
}

}  // namespace
}  // namespace reference
