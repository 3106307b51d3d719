// Uniform values from a case's bindings (run/CaseUniforms): names, literals of any shader
// type with their exact lengths, row_vector matrices transposed, a float3x3 from a 4x4
// quantity, and the errors a case author needs (uniform, expected and given count, line).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "run/CaseUniforms.h"

namespace shaderbed {
namespace {

UniformMember member(const std::string& name, uint32_t vecsize, uint32_t columns = 1, uint32_t array_size = 0,
                     bool is_float = true) {
  return UniformMember{.name = name, .is_float = is_float, .vecsize = vecsize, .columns = columns,
                       .array_size = array_size};
}

Binding named(const std::string& name, MatrixLayout layout = MatrixLayout::column_vector) {
  return Binding{.sources = {{name, {}}}, .layout = layout, .line = 7};
}
Binding literal(std::vector<double> v) { return Binding{.sources = {{"", std::move(v)}}, .line = 9}; }

const UniformBlock kBlock{.name = "LightBuffer"};

// A 4x4 with distinct entries, column-major: m[c * 4 + r] = 10 r + c (row r, column c).
std::vector<double> numbered_4x4() {
  std::vector<double> m(16);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[size_t(c) * 4 + r] = float(10 * r + c);
  return m;
}

TEST(CaseUniforms, LiteralsOfEveryShapeAreTakenAsWritten) {
  const BindingTable table{{"padding", literal({0.0})},
                           {"ambientColor", literal({0.1, 0.2, 0.3})},
                           {"lightCount", literal({3})},
                           {"useFog", literal({1})},
                           {"weights", literal({1, 2, 3, 4})},
                           {"basis", literal({1, 0, 0, 0, 1, 0, 0, 0, 1})}};
  const CaseUniforms u(table, {}, "case.toml");
  EXPECT_EQ(*u.value(kBlock, member("padding", 1)), (std::vector<double>{0}));
  EXPECT_EQ(*u.value(kBlock, member("ambientColor", 3)), (std::vector<double>{0.1, 0.2, 0.3}));
  EXPECT_EQ(*u.value(kBlock, member("lightCount", 1, 1, 0, false)), (std::vector<double>{3}));
  EXPECT_EQ(*u.value(kBlock, member("useFog", 1, 1, 0, false)), (std::vector<double>{1}));
  EXPECT_EQ(u.value(kBlock, member("weights", 1, 1, 4))->size(), 4u);   // float weights[4]
  EXPECT_EQ(u.value(kBlock, member("basis", 3, 3))->size(), 9u);        // float3x3
}

TEST(CaseUniforms, ALiteralOfTheWrongLengthNamesTheUniformTheCountsAndTheLine) {
  const BindingTable table{{"ambientColor", literal({0.1, 0.2, 0.3, 1.0})}, {"basis", literal({1, 0, 0, 1})}};
  const CaseUniforms u(table, {}, "case.toml");
  auto vector = u.value(kBlock, member("ambientColor", 3));
  ASSERT_FALSE(vector);
  EXPECT_EQ(vector.error().message, "uniform 'ambientColor' (float3) needs 3 values, the case gives 4");
  EXPECT_EQ(vector.error().line, 9);
  EXPECT_EQ(vector.error().file, "case.toml");
  auto matrix = u.value(kBlock, member("basis", 4, 4));
  ASSERT_FALSE(matrix);
  EXPECT_EQ(matrix.error().message, "uniform 'basis' (float4x4) needs 16 values, the case gives 4");
}

TEST(CaseUniforms, NamesAndLiteralsConcatenate) {
  const BindingTable table{{"SpecularColor", Binding{.sources = {{"specular", {}}, {"", {32}}}}}};
  const CaseUniforms u(table, {{"specular", {1, 0.5, 0.25}}}, "case.toml");
  EXPECT_EQ(*u.value(kBlock, member("SpecularColor", 4)), (std::vector<double>{1, 0.5, 0.25, 32}));
}

TEST(CaseUniforms, RowVectorLayoutUploadsTheTranspose) {
  const BindingTable table{{"column", named("m")}, {"row", named("m", MatrixLayout::row_vector)}};
  const CaseUniforms u(table, {{"m", numbered_4x4()}}, "case.toml");
  const std::vector<double> column = *u.value(kBlock, member("column", 4, 4));
  const std::vector<double> row = *u.value(kBlock, member("row", 4, 4));
  EXPECT_EQ(column, numbered_4x4());
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_EQ(row[size_t(c) * 4 + r], double(10 * c + r)) << r << "," << c;
}

TEST(CaseUniforms, RowVectorLayoutOnAVectorIsAnError) {
  const BindingTable table{{"LightDir", named("light_vector", MatrixLayout::row_vector)}};
  const CaseUniforms u(table, {{"light_vector", {0, 1, 0, 0}}}, "case.toml");
  auto v = u.value(kBlock, member("LightDir", 3));
  ASSERT_FALSE(v);
  EXPECT_NE(v.error().message.find("applies to matrices only"), std::string::npos) << v.error().message;
  EXPECT_EQ(v.error().line, 7);
}

TEST(CaseUniforms, AFloat3x3TakesTheUpperLeftOfA4x4Quantity) {
  const BindingTable table{{"World3", named("m")}};
  const CaseUniforms u(table, {{"m", numbered_4x4()}}, "case.toml");
  EXPECT_EQ(*u.value(kBlock, member("World3", 3, 3)), (std::vector<double>{0, 10, 20, 1, 11, 21, 2, 12, 22}));
}

TEST(CaseUniforms, AnUnknownSourceIsAnErrorWithItsLine) {
  const BindingTable table{{"Transform", named("tranform")}};
  const CaseUniforms u(table, {}, "case.toml");
  auto v = u.value(kBlock, member("Transform", 4, 4));
  ASSERT_FALSE(v);
  EXPECT_NE(v.error().message.find("'tranform', which is neither a scene quantity nor a parameter"), std::string::npos);
  EXPECT_EQ(v.error().line, 7);
}

TEST(CaseUniforms, TheCaseAmbientIsBindableAsAmbientLight) {
  Case c;
  c.ambient = glm::dvec3(0.1, 0.2, 0.3);
  c.params["diffuse"] = {1, 1, 1};
  const NamedValues values = bindable_values(SceneSetup{}, c);
  EXPECT_EQ(values.at("ambient_light"), (std::vector<double>{0.1, 0.2, 0.3, 1.0}));
  EXPECT_EQ(values.at("diffuse").size(), 3u);
  EXPECT_EQ(bindable_values(SceneSetup{}, Case{}).at("ambient_light"), (std::vector<double>{0, 0, 0, 1}));
}

}  // namespace
}  // namespace shaderbed
