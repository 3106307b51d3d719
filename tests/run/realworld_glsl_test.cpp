// The corpus's GLSL styles (tests/realworld/glsl110, glsl330) as their authors wrote them,
// through the runner on every path: a GL-tutorial shader on the fixed-function built-ins
// and a GLSL 3.30 core shader with loose uniforms pass on vulkan/spirv, gl/spirv, gl/cross
// and gl/glsl (Mesa's compiler, a compatibility context for the 1.10 one); each planted
// bug fails on every one of them.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "RealWorldRuns.h"
#include "run/Runner.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;
using test::kRealWorld;

Result<RunReport> run_cases(std::vector<std::string> cases) {
  RunOptions o;
  o.select.cases_dir = (kRealWorld / "cases").string();
  o.select.cases = std::move(cases);
  o.cell.size = 48;
  o.select.shapes = {"sphere", "torus"};
  o.cell.timing = {.warmup = 0, .runs = 0};
  return run_suite(o);
}

const std::set<std::string> kEveryGlslPath = {"vulkan/spirv", "gl/spirv", "gl/cross", "gl/glsl"};

class RealWorldGlsl : public ::testing::TestWithParam<std::string> {};

TEST_P(RealWorldGlsl, TheCorrectPortPassesOnEveryPath) {
  auto report = run_cases({GetParam()});
  ASSERT_TRUE(report) << report.error().to_string();
  const std::set<std::string> paths = test::paths_all_with_status(*report, "pass");
  EXPECT_EQ(paths, kEveryGlslPath);
  EXPECT_EQ(report->results.size(), 8u);
}

TEST_P(RealWorldGlsl, ThePlantedBugFailsOnEveryPath) {
  auto report = run_cases({GetParam() + "_bug"});
  ASSERT_TRUE(report) << report.error().to_string();
  EXPECT_EQ(test::paths_all_with_status(*report, "fail"), kEveryGlslPath);
  for (const CellResult& r : report->results) EXPECT_FALSE(r.message.empty()) << r.id();
}

INSTANTIATE_TEST_SUITE_P(Styles, RealWorldGlsl, ::testing::Values("glsl110_blinn_phong", "glsl330_blinn_phong"));

// A GL-era shader whose case forgets the light state hears of every missing uniform, by
// its legacy name, in one error (the matrices come from the scene).
TEST(RealWorldGlslBindings, UnboundLegacyStateIsListedByItsLegacyNames) {
  const fs::path root = fs::temp_directory_path() / ("shaderbed_glsl110_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "cases");
  fs::create_directory_symlink(kRealWorld / "glsl110", root / "glsl110");
  std::ofstream(root / "cases" / "glsl110_unbound.toml") << R"(model = "blinn_phong"
light = "point"
[params]
diffuse = [0.7, 0.5, 0.3]
specular = [0.3, 0.3, 0.3]
power = 12.0
[variants.pixel]
mode = "per_pixel"
glsl = { vertex = "glsl110/blinn_phong.vert", fragment = "glsl110/blinn_phong.frag" }
[bindings.glsl]
"gl_LightSource[0].position" = "light_position_view"
[tolerance]
interior = { max_abs = 1e-5, reason = "fp32" }
silhouette = { max_abs = 1e-4, reason = "edges" }
)";
  RunOptions o;
  o.select.cases_dir = (root / "cases").string();
  o.cell.size = 32;
  o.select.shapes = {"sphere"};
  o.cell.timing = {.warmup = 0, .runs = 0};
  auto report = run_suite(o);
  fs::remove_all(root);
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_FALSE(report->results.empty());
  for (const CellResult& r : report->results) {
    EXPECT_EQ(r.status, CellStatus::error) << r.id();
    for (const char* name : {"gl_LightSource[0].diffuse", "gl_LightSource[0].specular", "gl_FrontMaterial.shininess",
                             "gl_FrontMaterial.emission", "gl_LightModel.ambient"})
      EXPECT_NE(r.message.find(name), std::string::npos) << name << " in " << r.message;
    EXPECT_EQ(r.message.find("gl_ModelViewMatrix"), std::string::npos) << r.message;
  }
}

}  // namespace
}  // namespace shaderbed
