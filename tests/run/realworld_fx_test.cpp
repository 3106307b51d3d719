// The DX9 effect corpus style (tests/realworld/fx/): a D3D9-SDK-style .fx run unchanged
// through the effect front end (technique and pass from the case, row-vector D3DX
// matrices, a texture + sampler_state it does not read, CullMode/ZEnable states) passes
// on every HLSL path; its planted bug (H built from a reversed view vector) fails on
// every one; and a case that names a technique the effect lacks is one error at its line.
#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "RealWorldRuns.h"
#include "TempDir.h"
#include "run/Runner.h"
#include "scene/CaseFile.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;
using test::kRealWorld;

RunOptions quick(const std::string& cases_dir, const std::string& case_name) {
  return test::quick_run(cases_dir, case_name, 48);
}

TEST(RealWorldFx, SdkStyleEffectPassesOnEveryHlslPath) {
  auto report = run_suite(quick((kRealWorld / "cases").string(), "fx_blinn_phong"));
  ASSERT_TRUE(report) << report.error().to_string();
  const std::set<std::string> paths = test::paths_all_with_status(*report, "pass");
  EXPECT_EQ(paths, (std::set<std::string>{"vulkan/spirv", "gl/spirv", "gl/cross"}));
  EXPECT_EQ(report->results.size(), 6u);
}

TEST(RealWorldFx, HalfVectorBugFailsOnEveryPath) {
  auto report = run_suite(quick((kRealWorld / "cases").string(), "fx_blinn_phong_bug"));
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_EQ(report->results.size(), 6u);
  for (const CellResult& r : report->results) {
    EXPECT_EQ(r.status, CellStatus::fail) << r.id() << ": " << r.message;
    EXPECT_NE(r.message.find("interior pixels over"), std::string::npos) << r.message;
    // Only the specular term is wrong: at most the specular colour (0.3) off.
    EXPECT_GT(r.metrics.max_abs, 0.05) << r.id();
    EXPECT_LT(r.metrics.max_abs, 0.31) << r.id();
  }
}

TEST(RealWorldFx, TheOtherTechniqueIsPickedByTheCase) {
  // RenderSceneDiffuseOnly compiles RenderScenePS(false): no specular, so against
  // Blinn-Phong it must fail, and against Lambert it must pass.
  test::TempDir dir("realworld_fx");
  fs::create_directories(dir.path() / "fx");
  fs::copy_file(kRealWorld / "fx" / "blinn_phong.fx", dir.path() / "fx" / "blinn_phong.fx");
  std::ifstream in(kRealWorld / "cases" / "fx_blinn_phong.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("model = \"blinn_phong\"", "model = \"lambert\"");
  replace("technique = \"RenderSceneBlinnPhong\"", "technique = \"RenderSceneDiffuseOnly\"");
  // Declared, so bound, though this pass does not read them.
  replace("g_MaterialSpecular = \"specular\"\ng_fSpecularPower = \"power\"\n",
          "g_MaterialSpecular = [0.0, 0.0, 0.0]\ng_fSpecularPower = 1.0\n");
  replace("specular = [0.3, 0.3, 0.3]\npower = 12.0\n", "");
  dir.write("cases/diffuse.toml", text);
  RunOptions o = quick(dir / "cases", "diffuse");
  o.select.backends = {"vulkan"};
  auto report = run_suite(o);
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_EQ(report->results.size(), 2u);
  for (const CellResult& r : report->results) EXPECT_EQ(r.status, CellStatus::pass) << r.id() << ": " << r.message;

  replace("technique = \"RenderSceneDiffuseOnly\"", "technique = \"Shiny\"");
  dir.write("cases/missing.toml", text);
  o.select.cases = {"missing"};
  report = run_suite(o);
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_FALSE(report->results.empty());
  const CellResult& r = report->results.front();
  EXPECT_EQ(r.status, CellStatus::error);
  EXPECT_NE(r.message.find("missing.toml:11"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("no technique 'Shiny'"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("RenderSceneBlinnPhong, RenderSceneDiffuseOnly"), std::string::npos) << r.message;
}

TEST(RealWorldFx, TechniqueAndPassAreHlslShaderKeys) {
  test::TempDir dir("realworld_fx");
  const std::string path = dir.write("cases/t.toml",
                                     "model = \"lambert\"\n[params]\ndiffuse = [1.0, 1.0, 1.0]\n[variants.pixel]\n"
                                     "cg = { vertex = \"a.cg\", fragment = \"a.cg\", technique = \"T\" }\n"
                                     "[tolerance]\ninterior = { max_abs = 1e-5, reason = \"r\" }\n"
                                     "silhouette = { max_abs = 1e-4, reason = \"r\" }\n");
  auto c = load_case(path);
  ASSERT_FALSE(c);
  EXPECT_EQ(c.error().line, 5);
  EXPECT_NE(c.error().message.find("only hlsl shaders are effects"), std::string::npos) << c.error().message;
}

}  // namespace
}  // namespace shaderbed
