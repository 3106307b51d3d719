// Front-end gaps public shaders hit (issue 26 §6), each on a real-style shader of
// tests/realworld run unchanged, drawn for real: a DX9 effect whose texture is bound by
// the texture variable's name and whose tweakables keep their initial values; an effect
// whose D3D10 state objects sit under an #if that is off; WebGL 1 (unversioned GLSL ES
// 1.00) and WebGL 2 (#version 300 es) on every path, Mesa's own compiler included; and a
// mediump shader whose gl/glsl difference is named as reduced precision.
#include <set>

#include <gtest/gtest.h>

#include "RealWorldRuns.h"
#include "run/Runner.h"

namespace shaderbed {
namespace {

using test::kRealWorld;

RunReport run_case(const std::string& dir, const std::string& name) {
  auto report = run_suite(test::quick_run((kRealWorld / dir).string(), name, 48));
  EXPECT_TRUE(report) << report.error().to_string();
  return report ? std::move(*report) : RunReport{};
}

const std::set<std::string> kHlslPaths{"vulkan/spirv", "gl/spirv", "gl/cross"};
const std::set<std::string> kGlslPaths{"vulkan/spirv", "gl/glsl", "gl/spirv", "gl/cross"};

TEST(RealWorldEffectsEs, TextureByItsVariableNameAndInitialValuesAsDefaults) {
  const RunReport report = run_case("cases", "fx_textured_blinn_phong");
  EXPECT_EQ(test::paths_all_with_status(report, "pass"), kHlslPaths);
  EXPECT_EQ(report.results.size(), 6u);
}

TEST(RealWorldEffectsEs, D3D10StateObjectsUnderAnIfThatIsOffAreNotJudged) {
  const RunReport report = run_case("cases", "fx_lambert_sm4_fallback");
  EXPECT_EQ(test::paths_all_with_status(report, "pass"), kHlslPaths);
  EXPECT_EQ(report.results.size(), 6u);
}

TEST(RealWorldEffectsEs, UnversionedWebGl1RunsOnEveryPath) {
  const RunReport report = run_case("cases", "webgl_lambert");
  EXPECT_EQ(test::paths_all_with_status(report, "pass"), kGlslPaths);
  EXPECT_EQ(report.results.size(), 8u);
}

TEST(RealWorldEffectsEs, WebGl2Es300RunsOnEveryPath) {
  const RunReport report = run_case("cases", "webgl2_blinn_phong");
  EXPECT_EQ(test::paths_all_with_status(report, "pass"), kGlslPaths);
  EXPECT_EQ(report.results.size(), 8u);
}

TEST(RealWorldEffectsEs, MediumpOnMesasOwnCompilerIsNamedReducedPrecision) {
  const RunReport report = run_case("precision", "lambert_mediump");
  ASSERT_EQ(report.results.size(), 8u);
  for (const CellResult& r : report.results) {
    if (r.path != "glsl") {
      EXPECT_EQ(r.status, CellStatus::pass) << r.id() << ": " << r.message;
      continue;
    }
    // fp16 steps of 2^-11 near 1: well over fp32's tolerance, well under a wrong model's error.
    EXPECT_EQ(r.status, CellStatus::fail) << r.id();
    EXPECT_GT(r.metrics.max_abs, 1e-4) << r.id();
    EXPECT_LT(r.metrics.max_abs, 5e-3) << r.id();
    EXPECT_EQ(r.attribution, "reduced precision") << r.id() << ": " << r.attribution_reason;
    EXPECT_NE(r.attribution_reason.find("glsl on gl/glsl computes in reduced precision"), std::string::npos)
        << r.attribution_reason;
  }
}

}  // namespace
}  // namespace shaderbed
