// A case's [bindings.*] (names, literals, inline tables with a matrix layout), its
// [attributes.<language>] map and its scene keys (light, ambient): what loads, and what is
// refused with the line it is on.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "TempDir.h"
#include "scene/CaseFile.h"

namespace shaderbed {
namespace {

// A minimal case with `extra` (top-level keys and tables) after its variant.
Result<Case> load_with(const std::string& top, const std::string& tables) {
  static test::TempDir dir("case_bindings");
  const std::string text = "model = \"lambert\"\n" + top +
                           "[params]\ndiffuse = [1, 0.5, 0.25]\n"
                           "[variants.pixel]\n"
                           "glsl = { vertex = \"glsl/a.vert\", fragment = \"glsl/a.frag\" }\n" +
                           tables +
                           "[tolerance]\n"
                           "interior = { max_abs = 1e-4, reason = \"fp32\" }\n"
                           "silhouette = { max_abs = 1e-2, reason = \"edges\" }\n";
  return load_case(dir.write("cases/probe.toml", text));
}

TEST(CaseBindings, NamesLiteralsAndMixturesLoad) {
  auto c = load_with("", "[bindings.glsl]\n"
                         "mvp = \"transform\"\n"
                         "padding = 0.0\n"
                         "ambientColor = [0.1, 0.1, 0.1]\n"
                         "count = 3\n"
                         "useFog = true\n"
                         "specularPower = [\"diffuse\", 32.0]\n"
                         "rows = [[1, 0], [0, 1]]\n");
  ASSERT_TRUE(c) << c.error().to_string();
  const BindingTable& b = c->bindings.at(Language::glsl);
  EXPECT_EQ(b.at("mvp").single_name(), "transform");
  EXPECT_FALSE(b.at("mvp").literal());
  EXPECT_TRUE(b.at("padding").literal());
  EXPECT_EQ(b.at("padding").sources.at(0).literal, (std::vector<double>{0.0}));
  EXPECT_EQ(b.at("ambientColor").sources.at(0).literal, (std::vector<double>{0.1, 0.1, 0.1}));
  EXPECT_EQ(b.at("count").sources.at(0).literal, (std::vector<double>{3}));
  EXPECT_EQ(b.at("useFog").sources.at(0).literal, (std::vector<double>{1}));
  ASSERT_EQ(b.at("specularPower").sources.size(), 2u);
  EXPECT_EQ(b.at("specularPower").sources[0].name, "diffuse");
  EXPECT_EQ(b.at("specularPower").sources[1].literal, (std::vector<double>{32}));
  EXPECT_EQ(b.at("rows").sources.at(0).literal, (std::vector<double>{1, 0, 0, 1}));
  EXPECT_EQ(b.at("padding").line, 8);
  EXPECT_EQ(b.at("mvp").layout, MatrixLayout::column_vector);
}

TEST(CaseBindings, InlineTableGivesTheMatrixLayout) {
  auto c = load_with("", "[bindings.hlsl]\n"
                         "WorldViewProj = { value = \"transform\", layout = \"row_vector\" }\n"
                         "World = { value = \"world\", layout = \"column_vector\" }\n");
  ASSERT_TRUE(c) << c.error().to_string();
  const BindingTable& b = c->bindings.at(Language::hlsl);
  EXPECT_EQ(b.at("WorldViewProj").layout, MatrixLayout::row_vector);
  EXPECT_EQ(b.at("WorldViewProj").single_name(), "transform");
  EXPECT_EQ(b.at("World").layout, MatrixLayout::column_vector);
}

TEST(CaseBindings, ABadLayoutOrKeyIsRefusedWhereItIs) {
  auto layout = load_with("", "[bindings.hlsl]\nM = { value = \"transform\", layout = \"rows\" }\n");
  ASSERT_FALSE(layout);
  EXPECT_EQ(layout.error().line, 7);
  EXPECT_NE(layout.error().message.find("row_vector"), std::string::npos) << layout.error().message;
  auto key = load_with("", "[bindings.hlsl]\nM = { value = \"transform\", order = \"row\" }\n");
  ASSERT_FALSE(key);
  EXPECT_NE(key.error().message.find("unknown key 'order'"), std::string::npos) << key.error().message;
  auto no_value = load_with("", "[bindings.hlsl]\nM = { layout = \"row_vector\" }\n");
  ASSERT_FALSE(no_value);
  EXPECT_NE(no_value.error().message.find("needs value"), std::string::npos) << no_value.error().message;
}

TEST(CaseBindings, AttributeMapsByNameAndLocation) {
  auto c = load_with("", "[attributes.glsl]\naPos = \"position\"\n\"location 1\" = \"normal\"\nvCol = \"colour\"\n");
  ASSERT_TRUE(c) << c.error().to_string();
  const AttributeTable& a = c->attributes.at(Language::glsl);
  EXPECT_EQ(a.at("aPos"), "position");
  EXPECT_EQ(a.at("location 1"), "normal");
  EXPECT_EQ(a.at("vCol"), "colour");
  EXPECT_FALSE(c->attributes.contains(Language::hlsl));
}

TEST(CaseBindings, AnAttributeMapToNoStreamOrABadLocationIsRefused) {
  auto word = load_with("", "[attributes.glsl]\naPos = \"place\"\n");
  ASSERT_FALSE(word);
  EXPECT_EQ(word.error().line, 7);
  EXPECT_NE(word.error().message.find("'aPos'"), std::string::npos) << word.error().message;
  auto location = load_with("", "[attributes.glsl]\n\"location x\" = \"normal\"\n");
  ASSERT_FALSE(location);
  EXPECT_NE(location.error().message.find("location N"), std::string::npos) << location.error().message;
  auto language = load_with("", "[attributes.msl]\naPos = \"position\"\n");
  ASSERT_FALSE(language);
  EXPECT_NE(language.error().message.find("msl"), std::string::npos) << language.error().message;
}

TEST(CaseBindings, LightAndAmbientKeys) {
  auto defaults = load_with("", "");
  ASSERT_TRUE(defaults) << defaults.error().to_string();
  EXPECT_EQ(defaults->light, CaseLight::model_default);
  EXPECT_FALSE(defaults->ambient);
  auto point = load_with("light = \"point\"\nambient = [0.1, 0.2, 0.3]\n", "");
  ASSERT_TRUE(point) << point.error().to_string();
  EXPECT_EQ(point->light, CaseLight::point);
  ASSERT_TRUE(point->ambient);
  EXPECT_EQ(*point->ambient, glm::dvec3(0.1, 0.2, 0.3));
  auto bad_light = load_with("light = \"spot\"\n", "");
  ASSERT_FALSE(bad_light);
  EXPECT_EQ(bad_light.error().line, 2);
  auto bad_ambient = load_with("ambient = [0.1, 0.2]\n", "");
  ASSERT_FALSE(bad_ambient);
  EXPECT_NE(bad_ambient.error().message.find("[r, g, b]"), std::string::npos) << bad_ambient.error().message;
}

}  // namespace
}  // namespace shaderbed
