// `shaderbed explain` as a user runs it: a failing port's pixel line by line beside its
// original, a model case's beside the model's quantities, JSON for tools, and bad input as
// one line with exit status 2. Also `run`'s failure list naming the line (departs:).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ShellCommand.h"
#include "SourceTree.h"

namespace {

using shaderbed::test::kSource;
using shaderbed::test::shaderbed_cli;

const std::string differential = (kSource / "tests/differential/cases/tinted_diffuse.toml").string();
const std::string light_negated = "--cell light_negated/glsl/vulkan/spirv/sphere --size 48";

TEST(ExplainCli, AFailingPortsPixelLineByLineBesideItsOriginal) {
  const auto [status, out] = shaderbed_cli("explain " + differential + " " + light_negated);
  ASSERT_EQ(status, 0) << out;
  EXPECT_NE(out.find("tinted_diffuse/light_negated/glsl/vulkan/spirv/sphere: fail"), std::string::npos) << out;
  // The planted line is where it departs, and its value matches nothing of the original's.
  EXPECT_NE(out.find("departs: "), std::string::npos) << out;
  EXPECT_NE(out.find("glsl/light_negated.frag:14  colour = vec4(Tint * clamp(dot(n, -LightDir), 0.0, 1.0), 1.0);"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("each value beside what it matches in the original"), std::string::npos) << out;
  EXPECT_NE(out.find("   matches "), std::string::npos) << out;
  EXPECT_NE(out.find("colour = ("), std::string::npos) << out;
  EXPECT_NE(out.find("   matches nothing"), std::string::npos) << out;
}

TEST(ExplainCli, JsonForToolsAtTheChosenPixel) {
  const auto [status, out] = shaderbed_cli("explain " + differential + " " + light_negated + " --pixel 20,22 --json -");
  ASSERT_EQ(status, 0) << out;
  const auto j = nlohmann::json::parse(out, nullptr, false);
  ASSERT_FALSE(j.is_discarded()) << out;
  EXPECT_EQ(j["pixel"], nlohmann::json::array({20, 22}));
  EXPECT_EQ(j["against"], "the original");
  EXPECT_EQ(j["divergence"]["line"], 14);
  ASSERT_TRUE(j["lines"].is_array() && !j["lines"].empty()) << out;
  bool departs = false;
  for (const auto& line : j["lines"])
    for (const auto& v : line["values"]) departs = departs || (v["departs"].get<bool>() && line["line"] == 14);
  EXPECT_TRUE(departs) << out;
}

TEST(ExplainCli, AModelCasesShaderBesideTheModelsQuantities) {
  const std::string mutant = (kSource / "tests/mutants/cases/phong_reflect_sign.toml").string();
  const auto [status, out] = shaderbed_cli("explain " + mutant + " --cell pixel/glsl/vulkan/spirv/sphere --size 48");
  ASSERT_EQ(status, 0) << out;
  EXPECT_NE(out.find("departs: "), std::string::npos) << out;
  EXPECT_NE(out.find("phong_reflect_sign.frag:21  vec3 r = -reflect(-lightDirection, n);"), std::string::npos) << out;
  EXPECT_NE(out.find("matches nothing in the model"), std::string::npos) << out;
  EXPECT_NE(out.find("   matches the model's N\n"), std::string::npos) << out;
  EXPECT_NE(out.find("   matches the model's diffuse\n"), std::string::npos) << out;
}

TEST(ExplainCli, BadInputIsOneLineAndExitTwo) {
  for (const std::string& args : {light_negated + " --pixel 0,0", std::string("--cell light_negated/glsl --size 48"),
                                  light_negated + " --pixel twelve"}) {
    const auto [status, out] = shaderbed_cli("explain " + differential + " " + args);
    EXPECT_EQ(status, 2) << args << "\n" << out;
    EXPECT_EQ(out.rfind("shaderbed: explain: ", 0), 0u) << out;
    EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1) << out;
  }
}

TEST(ExplainCli, RunsFailureListNamesTheLineWhereAPortDeparts) {
  const auto [status, out] =
      shaderbed_cli("run --case " + differential + " --variant light_negated --backend vulkan --shape sphere --size 48 "
                    "--repeat 0 --quiet");
  EXPECT_EQ(status, 1) << out;
  EXPECT_NE(out.find("departs: "), std::string::npos) << out;
  EXPECT_NE(out.find("light_negated.frag:14"), std::string::npos) << out;
}

}  // namespace
