// The single-configuration API for `shaderbed eval`: default_params(), model_parameters()
// and evaluate() with its local-frame conventions and errors; and the defaults against
// the case files, which carry docs/models.md's values.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/ext/matrix_transform.hpp>
#include <sstream>

#include "ModelTestSupport.h"

namespace reference {
namespace {

using namespace testing;

TEST(Evaluate, DefaultParamsAreDocsModelsMd) {
  // A few spelled out (the case files check the rest, below).
  EXPECT_EQ(*default_params("ward_aniso"),
            (Params{{"diffuse", {1, 1, 1}}, {"specular", {1, 1, 1}}, {"roughness_xy", {0.9, 0.1}}}));
  EXPECT_EQ(*default_params("spot"), (Params{{"diffuse", {1, 1, 1}},
                                             {"light_color", {1, 1, 1}},
                                             {"attenuation", {0, 0.04, 0}},
                                             {"cos_umbra", {0.9659}},
                                             {"cos_penumbra", {0.8660}},
                                             {"falloff", {1}}}));
  EXPECT_EQ(*default_params("minnaert"), (Params{{"diffuse", {1, 1, 1}}, {"minnaert_power", {0.8}}}));
  EXPECT_EQ(model_parameters("cook_torrance"),
            (std::vector<std::string>{"diffuse", "fresnel_r0", "gaussian_c", "slope_m"}));
}

TEST(Evaluate, UnknownModel) {
  const auto defaults = default_params("ward");
  ASSERT_FALSE(defaults);
  EXPECT_NE(defaults.error().find("unknown lighting model 'ward'"), std::string::npos);
  EXPECT_NE(defaults.error().find("ward_iso"), std::string::npos) << "lists the known models";
  EXPECT_TRUE(model_parameters("ward").empty());
  const auto colour = evaluate("ward", {}, z_axis, z_axis);
  ASSERT_FALSE(colour);
  EXPECT_NE(colour.error().find("unknown lighting model 'ward'"), std::string::npos);
}

TEST(Evaluate, ParamsOverrideTheDefaults) {
  expect_colour_near(eval("lambert", {}, direction(60), z_axis), glm::dvec3(0.5));
  expect_colour_near(eval("lambert", {{"diffuse", {0.2, 0.4, 0.6}}}, direction(60), z_axis), {0.1, 0.2, 0.3});
  // Phong with only the power changed: D + S at the mirror direction is 2 whatever n is.
  expect_colour_near(eval("phong", {{"power", {100}}}, direction(30, 0), direction(30, 180)),
                     glm::dvec3(std::cos(glm::radians(30.0)) + 1));
  // An alpha component is accepted and ignored, as in case files.
  expect_colour_near(eval("ambient", {{"ambient", {0.1, 0.2, 0.3, 1}}}, z_axis, z_axis), {0.1, 0.2, 0.3});
}

TEST(Evaluate, UnknownParameterIsAnErrorButLutSizesAreIgnored) {
  const auto typo = evaluate("ward_iso", {{"roughnes", {0.3}}}, z_axis, z_axis);
  ASSERT_FALSE(typo);
  EXPECT_EQ(typo.error(), "ward_iso: unknown parameter 'roughnes' (parameters: diffuse, roughness, specular)");
  // A case file's parameters as they are, LUT sizes included.
  EXPECT_TRUE(evaluate("warn", {{"lut_size", {256}}, {"lut_rows", {64}}}, z_axis, z_axis));
  EXPECT_TRUE(evaluate("oren_nayar", {{"lut_size", {64}}}, z_axis, z_axis));
}

TEST(Evaluate, MalformedOrOutOfDomainParameters) {
  const auto two = evaluate("lambert", {{"diffuse", {1, 1}}}, z_axis, z_axis);
  ASSERT_FALSE(two);
  EXPECT_EQ(two.error(), "lambert: parameter 'diffuse' needs 3 or 4 values (a colour), got 2 value(s)");
  const auto zero = evaluate("ward_iso", {{"roughness", {0}}}, z_axis, z_axis);
  ASSERT_FALSE(zero);
  EXPECT_EQ(zero.error(), "ward_iso: parameter 'roughness' must be > 0 (sigma divides)");
}

TEST(Evaluate, DirectionsAreNormalised) {
  expect_colour_near(eval("blinn_phong", {}, {3, 0, 3}, {0, 0, 0.5}, {0, 0, 7}),
                     eval("blinn_phong", {}, direction(45), z_axis));
}

TEST(Evaluate, BadDirectionsAndDistancesAreErrors) {
  const glm::dvec3 zero(0.0), nan(NAN, 0, 1);
  EXPECT_EQ(evaluate("lambert", {}, zero, z_axis).error(), "L (to the light) must be a finite, non-zero vector");
  EXPECT_EQ(evaluate("lambert", {}, z_axis, nan).error(), "V (to the eye) must be a finite, non-zero vector");
  EXPECT_EQ(evaluate("lambert", {}, z_axis, z_axis, zero).error(), "N (the normal) must be a finite, non-zero vector");
  EXPECT_EQ(evaluate("lambert", {}, z_axis, z_axis, z_axis, nan).error(), "T (the tangent) must be finite");
  EXPECT_EQ(evaluate("warn", {}, z_axis, z_axis, z_axis, x_axis, 0).error(),
            "the light distance must be finite and > 0");
  EXPECT_FALSE(evaluate("warn", {}, z_axis, z_axis, z_axis, x_axis, -1));
  EXPECT_FALSE(evaluate("spot", {}, Configuration{z_axis, z_axis, z_axis, x_axis, 50, zero}));
}

TEST(Evaluate, PositionalAndStructFormsAgree) {
  const Configuration configuration{direction(30, 10), direction(50, 200), z_axis, direction(90, 40), 20, std::nullopt};
  for (const std::string& name : model_names()) {
    expect_colour_near(eval(name, {}, configuration),
                       eval(name, {}, configuration.to_light, configuration.to_eye, configuration.normal,
                            configuration.tangent, configuration.distance));
  }
}

TEST(Evaluate, ResultsDoNotDependOnTheFrame) {
  // The same configuration rotated as a whole (including the spot axis, -N by default,
  // and the tangent) gives the same colour: no model depends on the frame's axes.
  const glm::dmat3 rotation(glm::rotate(glm::dmat4(1.0), 1.1, glm::normalize(glm::dvec3(1, -2, 0.5))));
  const glm::dvec3 L = direction(35, 10), V = direction(50, 160), T = direction(90, 70);
  for (const std::string& name : model_names()) {
    expect_colour_near(eval(name, {}, rotation * L, rotation * V, rotation * z_axis, rotation * T),
                       eval(name, {}, L, V, z_axis, T), 1e-12);
  }
}

TEST(Evaluate, PointLightSitsAtDistanceAlongL) {
  // point_attenuated: cos(theta) / (0.04 d).
  expect_colour_near(eval("point_attenuated", {}, direction(60), z_axis), glm::dvec3(0.5 / 2));
  expect_colour_near(eval("point_attenuated", {}, direction(60), z_axis, z_axis, x_axis, 25), glm::dvec3(0.5));
  // Directional models ignore the distance.
  expect_colour_near(eval("lambert", {}, direction(60), z_axis, z_axis, x_axis, 3), glm::dvec3(0.5));
}

TEST(Evaluate, EvaluateEqualsTheModelInTheCaseScene) {
  // evaluate() in its local frame against make_model() in the case scene's geometry: the
  // top of a sphere under the light at (0, 50, 0) shining down, the eye at (-100, 50, 0).
  const glm::dvec3 point(0, 25, 0), normal(0, 1, 0), light(0, 50, 0), eye(-100, 50, 0);
  const glm::dvec3 to_eye = glm::normalize(eye - point);
  for (const std::string& name : model_names()) {
    Shader shader(name);
    const glm::dvec3 scene_colour = shader.shade({point, normal, x_axis, {0, 0}}, {normal, light, eye});
    // Directional light (0, 1, 0) = N; point light 25 above along N; spot axis -N.
    expect_colour_near(eval(name, {}, normal, to_eye, normal, x_axis, 25), scene_colour, 1e-12);
  }
}

// ---- the case files ----------------------------------------------------------------------

// The [params] table of shaders/cases/<model>.toml: `name = number` or `name = [numbers]`,
// comments stripped. Enough TOML for these files.
std::optional<Params> case_params(const std::string& model) {
  std::ifstream file(std::string(SHADERBED_SOURCE_DIR) + "/shaders/cases/" + model + ".toml");
  if (!file) return std::nullopt;
  Params params;
  bool in_params = false;
  for (std::string line; std::getline(file, line);) {
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    if (line.find('[') == line.find_first_not_of(" \t")) {
      in_params = line.find("[params]") != std::string::npos;
      continue;
    }
    if (!in_params) continue;
    const size_t equals = line.find('=');
    if (equals == std::string::npos) continue;
    std::string name = line.substr(0, equals);
    name.erase(name.find_last_not_of(" \t") + 1);
    name.erase(0, name.find_first_not_of(" \t"));
    std::string values = line.substr(equals + 1);
    for (char& ch : values) {
      if (ch == '[' || ch == ']' || ch == ',') ch = ' ';
    }
    std::istringstream stream(values);
    std::vector<double> numbers;
    for (double value; stream >> value;) numbers.push_back(value);
    params[name] = numbers;
  }
  return params;
}

TEST(Evaluate, CaseFilesCarryExactlyTheDefaults) {
  // docs/models.md: the case parameters with the book's values as defaults. Every model
  // parameter is in its case file with the default value; the case may add LUT sizes.
  for (const std::string& name : model_names()) {
    const std::optional<Params> params = case_params(name);
    if (!params) {
      ADD_FAILURE() << "no shaders/cases/" << name << ".toml";
      continue;
    }
    Params model_only = *params;
    model_only.erase("lut_size");
    model_only.erase("lut_rows");
    EXPECT_EQ(model_only, *default_params(name)) << name;
    EXPECT_TRUE(make_model(name, *params)) << name;
    EXPECT_TRUE(evaluate(name, *params, z_axis, z_axis)) << name;
  }
}

}  // namespace
}  // namespace reference
