// The SH cases end to end (harness/prt, docs/sh-lighting.md): every cell
// passes against the truncated SH in double, carries its error against the exact
// integral, and the approximation's own error falls as bands are added.
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ShellCommand.h"
#include "TempDir.h"

namespace {

using nlohmann::json;

json run_json(const std::string& args, const std::filesystem::path& file) {
  const auto [status, out] = shaderbed::test::run_shell(std::string(SHADERBED_BINARY) + " run " + args +
                                                        " --size 48 --repeat 0 --quiet --json " + file.string());
  EXPECT_LE(status, 1) << out;
  std::ifstream in(file);
  return json::parse(in);
}

TEST(ShCases, EveryCellPassesAndReportsItsErrorAgainstTheExactIntegral) {
  shaderbed::test::TempDir dir;
  const json report = run_json("--case sh,sh_cpca,sh_irradiance,sh_specular --shape sphere,torus", dir.path() / "sh.json");
  ASSERT_FALSE(report["results"].empty());
  for (const json& r : report["results"]) {
    EXPECT_EQ(r["status"], "pass") << r["id"] << ": " << r["message"];
    ASSERT_TRUE(r.contains("sh")) << r["id"];
    const double truncation = r["sh"]["truncation"], render_vs_exact = r["sh"]["render_vs_exact"];
    EXPECT_GT(truncation, 0.0) << r["id"];   // a 4-band delta light is not exact
    EXPECT_LE(truncation, double(r["sh"]["bound"])) << r["id"];
    // The render's error against the exact integral is the approximation's plus fp32.
    EXPECT_NEAR(render_vs_exact, truncation, 1e-4) << r["id"];
  }
}

TEST(ShCases, TheApproximationErrorFallsWithBands) {
  shaderbed::test::TempDir dir;
  std::map<int, double> by_bands;
  for (int bands : {1, 2, 4}) {
    const json report = run_json("--case sh --variant vertex --shape sphere --lang glsl --backend vulkan --param bands=" +
                                     std::to_string(bands) + " --param grid=12",
                                 dir.path() / ("b" + std::to_string(bands) + ".json"));
    ASSERT_EQ(report["results"].size(), 1u);
    by_bands[bands] = report["results"][0]["sh"]["truncation"];
  }
  EXPECT_GT(by_bands[1], by_bands[2]);
  EXPECT_GT(by_bands[2], by_bands[4]);
}

TEST(ShCases, TheTextureVariantTakesEightBands) {
  shaderbed::test::TempDir dir;
  const json report = run_json("--case sh --variant texture --shape sphere --param bands=8", dir.path() / "b8.json");
  ASSERT_FALSE(report["results"].empty());
  for (const json& r : report["results"]) {
    EXPECT_EQ(r["status"], "pass") << r["id"] << ": " << r["message"];
    EXPECT_EQ(double(r["sh"]["bytes_per_vertex"]), 3 * 64 * 4.0) << r["id"];
  }
}

TEST(ShCases, BadSettingsAreInputErrors) {
  const auto [status, out] =
      shaderbed::test::run_shell(std::string(SHADERBED_BINARY) + " run --case sh --param bands=9 --size 32 --quiet");
  EXPECT_NE(status, 0);
  EXPECT_NE(out.find("bands"), std::string::npos) << out;
}

}  // namespace
