// Every command that compiles a user's shader outside `run` (init, port, stats, sweep,
// hard) compiles it in a child process (compile/IsolatedCompile.h): a shader that crashes
// glslang 12 (an HLSL entry parameter without a name, as in tests/run/isolation_test.cpp)
// costs an error line naming the file, never the command. Real glslang, real binary.
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "FileContents.h"
#include "ShellCommand.h"
#include "TempDir.h"

namespace {

using shaderbed::test::read_json;
using shaderbed::test::shaderbed_cli;
using shaderbed::test::TempDir;

const std::string kShaders = std::string(SHADERBED_SOURCE_DIR) + "/shaders/";

const char* const kCrashingPixelStage = R"(// A pixel stage with an unnamed parameter (crashes glslang 12).
float4 main(int) : COLOR0 { return 1; }
)";

// A Lambert case (the library's per-pixel variant's bindings) whose pixel stage is `fragment`.
std::string lambert_case(const TempDir& dir, const std::string& name, const std::string& fragment) {
  return dir.write("cases/" + name + ".toml",
                   "model = \"lambert\"\n"
                   "description = \"Lambert per pixel.\"\n"
                   "[params]\ndiffuse = [1.0, 1.0, 1.0]\n"
                   "[variants.pixel]\nmode = \"per_pixel\"\n"
                   "hlsl = { vertex = \"" + kShaders + "hlsl/setup_vs.hlsl\", fragment = \"" + fragment + "\" }\n"
                   "[bindings.hlsl]\nTransform = \"transform\"\nLightVector = \"light_vector\"\nDiffuseColor = \"diffuse\"\n"
                   "[tolerance]\ninterior = { max_abs = 1e-05, reason = \"test\" }\n"
                   "silhouette = { max_abs = 1e-04, reason = \"test\" }\n");
}

struct Crasher {
  TempDir dir{"isolated_compile"};
  std::string shader = dir.write("crash_ps.hlsl", kCrashingPixelStage);
  std::string the_case = lambert_case(dir, "crash", shader);
};

// Exited by itself (not by a signal), and said what crashed, on a `shaderbed:` line.
void expect_reported(int status, const std::string& out, const std::string& prefix) {
  EXPECT_GE(status, 0) << "ended by a signal:\n" << out;
  EXPECT_NE(status, 0) << out;
  const size_t at = out.find(prefix);
  ASSERT_NE(at, std::string::npos) << out;
  const std::string line = out.substr(at, out.find('\n', at) - at);
  EXPECT_NE(line.find("crash_ps.hlsl"), std::string::npos) << line;
  EXPECT_NE(line.find("compile"), std::string::npos) << line;
  EXPECT_NE(line.find("glslang crashed (signal 11, SIGSEGV)"), std::string::npos) << line;
}

TEST(IsolatedCompile, InitReportsTheCrashAsBadInputAndWritesNoCase) {
  Crasher c;
  const std::string vertex = c.dir.write("vs.hlsl", shaderbed::test::read_text(kShaders + "hlsl/setup_vs.hlsl"));
  const std::string out = c.dir / "drafted.toml";
  const auto [status, text] = shaderbed_cli("init " + vertex + " " + c.shader + " --no-run --out " + out);
  expect_reported(status, text, "shaderbed: init: ");
  EXPECT_EQ(status, 2) << text;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(IsolatedCompile, PortReportsTheCrashAsBadInput) {
  Crasher c;
  const auto [status, text] = shaderbed_cli("port " + c.the_case + " --to glsl --out-dir " + (c.dir / "port"));
  expect_reported(status, text, "shaderbed: ");
  EXPECT_EQ(status, 2) << text;
}

TEST(IsolatedCompile, StatsReportsTheCrashAsAnErrorRowAndCountsTheOtherCases) {
  Crasher c;
  lambert_case(c.dir, "good", kShaders + "hlsl/lambert_ps.hlsl");
  const std::string json_path = c.dir / "stats.json";
  const auto [status, text] = shaderbed_cli("stats --no-nir --quiet --cases-dir " + (c.dir / "cases") + " --json " + json_path);
  expect_reported(status, text, "shaderbed: stats: crash/pixel/hlsl/");
  EXPECT_EQ(status, 1) << text;
  int good = 0, crashed = 0;
  const nlohmann::json report = read_json(json_path);
  for (const nlohmann::json& e : report.at("entries")) {
    if (e["case"] == "good") {
      EXPECT_FALSE(e.contains("error")) << e.dump();
      EXPECT_GT(e["spirv"]["total"].get<int>(), 0) << e.dump();
      ++good;
    } else {
      EXPECT_NE(e.value("error", "").find("glslang crashed"), std::string::npos) << e.dump();
      ++crashed;
    }
  }
  EXPECT_EQ(good, 2);
  EXPECT_EQ(crashed, 2);
}

TEST(IsolatedCompile, SweepReportsTheCrashAsAnErrorPoint) {
  Crasher c;
  const auto [status, text] = shaderbed_cli("sweep crash --cases-dir " + (c.dir / "cases") +
                                            " --lang hlsl --size 16 --repeat 1 --warmup 0");
  expect_reported(status, text, "shaderbed: sweep: ");
}

TEST(IsolatedCompile, HardReportsTheCrashForAUsersCase) {
  Crasher c;
  const auto [status, text] = shaderbed_cli("hard --case " + c.the_case + " --backend vulkan --scenario long_normals --size 16");
  expect_reported(status, text, "shaderbed: hard: ");
}

}  // namespace
