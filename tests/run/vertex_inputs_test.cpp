// Vertex inputs to mesh streams (backends/VertexInputs): the case's map by name and by
// location before semantics and names, the vertex colour stream, one error for every
// unmatched input; then a shader that reads its normal from the vertex colour, its inputs
// mapped in [attributes.glsl], through the runner on every path of both backends.
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "RealWorldRuns.h"
#include "TempDir.h"
#include "backends/VertexInputs.h"
#include "run/Runner.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;
using test::kRealWorld;

StageInput input(uint32_t location, const std::string& name, const std::string& semantic = "") {
  return StageInput{.location = location, .name = name, .semantic = semantic};
}

TEST(VertexInputs, ColourBySemanticAndByName) {
  for (const StageInput& in : {input(3, "input.Packed", "COLOR0"), input(3, "input.Packed", "COLOR"),
                               input(2, "color"), input(2, "aColour"), input(2, "in_color")}) {
    auto s = attribute_stream_for(in);
    ASSERT_TRUE(s) << in.name << " " << in.semantic << ": " << s.error().message;
    EXPECT_EQ(s->attribute, VertexAttribute::color) << in.name;
    EXPECT_EQ(s->offset, offsetof(Vertex, color));
    EXPECT_EQ(s->components, 4u);
  }
}

TEST(VertexInputs, TheCaseMapComesFirstByNameThenByLocation) {
  const AttributeTable map{{"normal", "color"}, {"location 1", "texcoord"}};
  // By name: an input the heuristic would call a normal is the colour stream.
  EXPECT_EQ(attribute_stream_for(input(0, "normal"), &map)->attribute, VertexAttribute::color);
  // By location.
  EXPECT_EQ(attribute_stream_for(input(1, "whatever"), &map)->attribute, VertexAttribute::texcoord);
  // Unmapped inputs still go by semantic and name.
  EXPECT_EQ(attribute_stream_for(input(2, "aPos"), &map)->attribute, VertexAttribute::position);
  EXPECT_EQ(attribute_stream_for(input(3, "p", "TANGENT0"), &map)->attribute, VertexAttribute::tangent);
}

TEST(VertexInputs, EveryUnmatchedInputIsListedInOneErrorWithTheHint) {
  const std::vector<StageInput> inputs{input(0, "aPos"), input(1, "inNrm"), input(2, "vtxShade")};
  auto streams = attribute_streams_for(inputs, nullptr, Language::glsl);
  ASSERT_FALSE(streams);
  const std::string& m = streams.error().message;
  EXPECT_NE(m.find("vertex inputs 'inNrm' at location 1, 'vtxShade' at location 2 are not mesh attributes"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("[attributes.glsl]"), std::string::npos) << m;
  EXPECT_NE(m.find("inNrm = \"normal\" or \"location 1\" = \"normal\""), std::string::npos) << m;
  const AttributeTable map{{"inNrm", "normal"}, {"location 2", "color"}};
  auto mapped = attribute_streams_for(inputs, &map, Language::glsl);
  ASSERT_TRUE(mapped) << mapped.error().message;
  ASSERT_EQ(mapped->size(), 3u);
  EXPECT_EQ((*mapped)[1].attribute, VertexAttribute::normal);
  EXPECT_EQ((*mapped)[2].attribute, VertexAttribute::color);
}

TEST(VertexInputs, AMapToAWordThatIsNoStreamSaysSo) {
  const AttributeTable map{{"aPos", "place"}};
  auto streams = attribute_streams_for({input(0, "aPos")}, &map, Language::glsl);
  ASSERT_FALSE(streams);
  EXPECT_NE(streams.error().message.find("mapped to 'place'"), std::string::npos) << streams.error().message;
}

RunOptions small_vertex_run(const std::string& cases_dir) {
  RunOptions o;
  o.select.cases_dir = cases_dir;
  o.select.cases = {"glsl_lambert_packed_normal"};
  o.cell.size = 48;
  o.select.shapes = {"sphere", "cone"};
  o.cell.timing = {.warmup = 0, .runs = 0};
  return o;
}

TEST(VertexInputs, NormalsReadFromTheVertexColourPassOnEveryPath) {
  auto report = run_suite(small_vertex_run((kRealWorld / "cases").string()));
  ASSERT_TRUE(report) << report.error().to_string();
  std::set<std::string> paths;
  for (const CellResult& r : report->results) {
    EXPECT_EQ(r.status, CellStatus::pass) << r.id() << ": " << r.message << " / " << r.attribution_reason;
    paths.insert(r.language + " " + r.backend + "/" + r.path);
  }
  EXPECT_EQ(paths, (std::set<std::string>{"glsl vulkan/spirv", "glsl gl/glsl", "glsl gl/spirv", "glsl gl/cross",
                                          "hlsl vulkan/spirv", "hlsl gl/spirv", "hlsl gl/cross"}));
}

TEST(VertexInputs, WithoutTheMapTheUnmatchedInputIsNamedOnEveryPath) {
  const test::TempDir dir("vertex_inputs");
  std::ifstream in(kRealWorld / "cases" / "glsl_lambert_packed_normal.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string map = "\"location 1\" = \"color\"\n";
  ASSERT_NE(text.find(map), std::string::npos);
  text.erase(text.find(map), map.size());
  for (const char* folder : {"glsl", "hlsl"}) fs::create_directory_symlink(kRealWorld / folder, dir.path() / folder);
  dir.write("cases/glsl_lambert_packed_normal.toml", text);
  RunOptions o = small_vertex_run((dir.path() / "cases").string());
  o.select.languages = {"glsl"};
  auto report = run_suite(o);
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_EQ(report->results.size(), 8u);
  for (const CellResult& r : report->results) {
    EXPECT_EQ(r.status, CellStatus::error) << r.id();
    EXPECT_NE(r.message.find("'aPackedNormal' at location 1"), std::string::npos) << r.id() << ": " << r.message;
    EXPECT_NE(r.message.find("[attributes.glsl]"), std::string::npos) << r.message;
  }
}

}  // namespace
}  // namespace shaderbed
