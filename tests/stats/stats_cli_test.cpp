// `shaderbed stats` end to end: JSON out, and a baseline comparison whose exit status
// gates CI (--fail-above).
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

std::pair<int, std::string> cli(const std::string& args) {
  std::string out;
  FILE* p = popen((std::string(SHADERBED_BINARY) + " " + args + " 2>&1").c_str(), "r");
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

TEST(StatsCli, BaselineReportsHelpedAndHurtAndGatesOnThreshold) {
  const fs::path dir = fs::temp_directory_path() / ("shaderbed_stats_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string now = (dir / "now.json").string(), old = (dir / "old.json").string();
  auto [status, out] = cli("stats --no-nir --case phong --lang glsl,hlsl --quiet --json " + now);
  ASSERT_EQ(status, 0) << out;
  // The baseline: every fragment shader 25% smaller, so the current run is HURT.
  nlohmann::json j = nlohmann::json::parse(std::ifstream(now));
  ASSERT_FALSE(j["entries"].empty());
  for (auto& e : j["entries"])
    if (e["stage"] == "fragment") e["spirv_opt"]["total"] = int(e["spirv_opt"]["total"].get<int>() * 0.75);
  std::ofstream(old) << j.dump();

  auto [hurt_status, hurt] = cli("stats --from " + now + " --baseline " + old + " --fail-above 5");
  EXPECT_EQ(hurt_status, 1) << hurt;
  EXPECT_NE(hurt.find("HURT"), std::string::npos) << hurt;
  auto [lenient_status, lenient] = cli("stats --from " + now + " --baseline " + old + " --fail-above 80");
  EXPECT_EQ(lenient_status, 0) << lenient;
  auto [helped_status, helped] = cli("stats --from " + old + " --baseline " + now + " --fail-above 5");
  EXPECT_EQ(helped_status, 0) << helped;
  EXPECT_NE(helped.find("helped"), std::string::npos) << helped;
  fs::remove_all(dir);
}

}  // namespace
