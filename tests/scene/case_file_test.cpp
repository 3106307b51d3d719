// Case files: the library's cases load; malformed ones fail with file, line and column.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "scene/CaseFile.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;
const fs::path kCases = fs::path(SHADERBED_SOURCE_DIR) / "shaders" / "cases";

// Writes a case into a temporary shaders/cases tree that can see the real shader files.
class TempCase : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("shaderbed_case_test_" + std::to_string(::getpid()));
    fs::create_directories(root_ / "cases");
    fs::create_directory_symlink(kCases.parent_path() / "glsl", root_ / "glsl");
  }
  void TearDown() override { fs::remove_all(root_); }
  std::string write(const std::string& text) {
    const fs::path p = root_ / "cases" / "probe.toml";
    std::ofstream(p) << text;
    return p.string();
  }
  fs::path root_;
};

TEST(CaseFile, LibraryCasesLoad) {
  auto cases = load_cases(kCases.string());
  ASSERT_TRUE(cases) << cases.error().to_string();
  ASSERT_GE(cases->size(), 3u);
  for (const Case& c : *cases) {
    EXPECT_FALSE(c.interior.reason.empty()) << c.name;
    EXPECT_FALSE(c.variants.empty()) << c.name;
    for (const Variant& v : c.variants) EXPECT_TRUE(v.shaders.contains(Language::glsl)) << c.name << "/" << v.name;
  }
}

TEST_F(TempCase, SyntaxErrorHasLineAndColumn) {
  auto c = load_case(write("model = \"lambert\"\n\n[params]\ndiffuse = [1 1]\npower = 7\n"));
  ASSERT_FALSE(c);
  EXPECT_EQ(c.error().line, 4);
  EXPECT_GT(c.error().column, 0);
  EXPECT_NE(c.error().file.find("probe.toml"), std::string::npos);
}

TEST_F(TempCase, BadValueIsReportedWhereItIs) {
  auto c = load_case(write("model = \"lambert\"\n"
                           "[params]\n"
                           "diffuse = \"white\"\n"));
  ASSERT_FALSE(c);
  EXPECT_EQ(c.error().line, 3);
  EXPECT_NE(c.error().message.find("diffuse"), std::string::npos);
}

TEST_F(TempCase, ToleranceWithoutReasonIsRefused) {
  auto c = load_case(write("model = \"lambert\"\n"
                           "[variants.pixel]\n"
                           "glsl = { vertex = \"glsl/setup.vert\", fragment = \"glsl/lambert.frag\" }\n"
                           "[tolerance]\n"
                           "interior = { max_abs = 1e-4 }\n"
                           "silhouette = { max_abs = 1e-2, reason = \"edges\" }\n"));
  ASSERT_FALSE(c);
  EXPECT_EQ(c.error().line, 5);
  EXPECT_NE(c.error().message.find("reason"), std::string::npos);
}

TEST_F(TempCase, ShaderFilesRememberWhereTheCaseNamesThem) {
  auto c = load_case(write("model = \"lambert\"\n"
                           "[variants.pixel]\n"
                           "glsl = { vertex = \"glsl/nope.vert\", fragment = \"glsl/lambert.frag\" }\n"
                           "[tolerance]\n"
                           "interior = { max_abs = 1e-4, reason = \"fp32\" }\n"
                           "silhouette = { max_abs = 1e-2, reason = \"edges\" }\n"));
  ASSERT_TRUE(c) << c.error().to_string();
  EXPECT_EQ(c->variants[0].shaders.at(Language::glsl).line, 3) << "a missing file is reported at this line";
  EXPECT_NE(c->variants[0].shaders.at(Language::glsl).vertex.find("nope.vert"), std::string::npos);
}

TEST_F(TempCase, MinimalCaseLoads) {
  auto c = load_case(write("model = \"lambert\"\n"
                           "[params]\ndiffuse = [1, 0.5, 0.25]\n"
                           "[variants.pixel]\n"
                           "glsl = { vertex = \"glsl/setup.vert\", fragment = \"glsl/lambert.frag\" }\n"
                           "[bindings.glsl]\nmodelViewProjection = \"transform\"\nspec = [\"a\", \"b\"]\n"
                           "[tolerance]\n"
                           "interior = { max_abs = 1e-4, reason = \"fp32\" }\n"
                           "silhouette = { max_abs = 1e-2, reason = \"edges\" }\n"));
  ASSERT_TRUE(c) << c.error().to_string();
  EXPECT_EQ(c->model, "lambert");
  EXPECT_EQ(c->params.at("diffuse"), (std::vector<double>{1, 0.5, 0.25}));
  EXPECT_EQ(c->variants[0].mode, LightingMode::per_pixel);
  const Binding& spec = c->bindings.at(Language::glsl).at("spec");
  ASSERT_EQ(spec.sources.size(), 2u);
  EXPECT_EQ(spec.sources[0].name, "a");
  EXPECT_EQ(spec.sources[1].name, "b");
}

}  // namespace
// A variant's shaders with `extra` added to the language's inline table.
std::string entry_case(const std::string& language, const std::string& extra) {
  return "model = \"lambert\"\n"
         "[variants.pixel]\n" +
         language + " = { vertex = \"x/one.hlsl\", fragment = \"x/one.hlsl\"" + extra + " }\n"
         "[tolerance]\n"
         "interior = { max_abs = 1e-4, reason = \"fp32\" }\n"
         "silhouette = { max_abs = 1e-2, reason = \"edges\" }\n";
}

TEST_F(TempCase, EntryPointsDefaultToMainAndCanBeNamedPerStage) {
  auto plain = load_case(write(entry_case("hlsl", "")));
  ASSERT_TRUE(plain) << plain.error().to_string();
  EXPECT_EQ(plain->variants[0].shaders.at(Language::hlsl).vertex_entry, "main");
  EXPECT_EQ(plain->variants[0].shaders.at(Language::hlsl).fragment_entry, "main");

  auto named = load_case(write(entry_case("hlsl", ", vertex_entry = \"LightVS\", fragment_entry = \"LightPS\"")));
  ASSERT_TRUE(named) << named.error().to_string();
  const ShaderFiles& f = named->variants[0].shaders.at(Language::hlsl);
  EXPECT_EQ(f.vertex_entry, "LightVS");
  EXPECT_EQ(f.fragment_entry, "LightPS");
  EXPECT_EQ(f.vertex, f.fragment) << "one file may hold both stages";
}

TEST_F(TempCase, BadEntryKeysAreErrorsAtTheirLine) {
  struct Bad {
    std::string language, extra, says;
  };
  for (const Bad& b : {Bad{"hlsl", ", vertex_entyr = \"LightVS\"", "unknown key 'vertex_entyr'"},
                       Bad{"hlsl", ", fragment_entry = \"\"", "fragment_entry must name a function"},
                       Bad{"hlsl", ", fragment_entry = 3", "fragment_entry must name a function"},
                       Bad{"glsl", ", vertex_entry = \"vs_main\"", "GLSL stages are entered at main()"}}) {
    auto c = load_case(write(entry_case(b.language, b.extra)));
    ASSERT_FALSE(c) << b.extra;
    EXPECT_NE(c.error().message.find(b.says), std::string::npos) << c.error().to_string();
    EXPECT_EQ(c.error().line, 3) << c.error().to_string();
  }
  EXPECT_TRUE(load_case(write(entry_case("glsl", ", vertex_entry = \"main\""))));
}

}  // namespace shaderbed
