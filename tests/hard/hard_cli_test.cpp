// `shaderbed hard`: exit status, one-line errors and the JSON it writes.
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int status;
  std::string err;
};

CliRun shaderbed(const std::string& args) {
  const fs::path err = fs::temp_directory_path() / ("hard_cli_" + std::to_string(::getpid()) + ".err");
  const std::string command = std::string(SHADERBED_BINARY) + " hard " + args + " > /dev/null 2> " + err.string();
  const int raw = std::system(command.c_str());
  std::ifstream in(err);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  fs::remove(err);
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, text};
}

TEST(HardCli, PassingModelExitsZeroAndWritesJson) {
  const fs::path json = fs::temp_directory_path() / ("hard_cli_" + std::to_string(::getpid()) + ".json");
  const CliRun r = shaderbed("--case lambert --lang glsl --size 17 --json " + json.string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  fs::remove(json);
  EXPECT_EQ(j["size"], 17);
  ASSERT_FALSE(j["rows"].empty());
  for (const auto& row : j["rows"]) {
    EXPECT_EQ(row["case"], "lambert");
    EXPECT_EQ(row["status"], "pass");
    EXPECT_TRUE(row.contains("nonfinite") && row.contains("max_relative") && row.contains("max_ulps"));
  }
  ASSERT_EQ(j["models"].size(), 1u);
  EXPECT_EQ(j["models"][0]["robust"], "not needed");
  EXPECT_TRUE(j["models"][0]["robust_variant"].is_null());
  EXPECT_TRUE(j["scenarios"].contains("sphere_perpendicular"));
}

TEST(HardCli, AllPathsGivesARowPerGlPath) {
  const fs::path json = fs::temp_directory_path() / ("hard_cli_paths_" + std::to_string(::getpid()) + ".json");
  const CliRun r = shaderbed("--case lambert --lang glsl --backend gl --scenario sphere_perpendicular --size 17 "
                             "--all-paths --json " + json.string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  fs::remove(json);
  std::set<std::string> paths;
  for (const auto& row : j["rows"]) paths.insert(row["path"].get<std::string>());
  EXPECT_EQ(paths, (std::set<std::string>{"glsl", "spirv", "cross"}));
}

TEST(HardCli, FailingRowExitsOne) {
  const CliRun r = shaderbed("--cases-dir " + (fs::path(SHADERBED_SOURCE_DIR) / "tests" / "hard" / "cases").string() +
                          " --lang glsl --size 17 --scenario sphere_perpendicular");
  EXPECT_EQ(r.status, 1) << r.err;
}

TEST(HardCli, BadInputExitsTwoWithOneLine) {
  for (const char* args : {"--case no_such_case", "--backend metal", "--scenario nope", "--size 1"}) {
    const CliRun r = shaderbed(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.err.find("shaderbed: hard:"), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
}

// A user's case file: its shaders on the slices against their own double twin. The naive
// Gaussian lobe (tan^2 from 1 - (N.H)^2) fails at the sharp lobe's peak, and the table
// names the line that cancels; the robust one (|N x H|^2) passes.
TEST(HardCli, UserCaseNamesTheLineThatLosesSignificance) {
  const fs::path json = fs::temp_directory_path() / ("hard_cli_user_" + std::to_string(::getpid()) + ".json");
  const fs::path out = fs::temp_directory_path() / ("hard_cli_user_" + std::to_string(::getpid()) + ".out");
  const std::string user_case = (fs::path(SHADERBED_SOURCE_DIR) / "tests" / "hard" / "user" / "gaussian_lobe.toml").string();
  const std::string command = std::string(SHADERBED_BINARY) + " hard --case " + user_case +
                              " --backend vulkan --scenario lobe_sharp,sphere_perpendicular --size 17 --json " +
                              json.string() + " > " + out.string() + " 2>&1";
  const int raw = std::system(command.c_str());
  std::ifstream printed(out);
  const std::string table((std::istreambuf_iterator<char>(printed)), std::istreambuf_iterator<char>());
  fs::remove(out);
  ASSERT_TRUE(WIFEXITED(raw)) << table;
  EXPECT_EQ(WEXITSTATUS(raw), 1) << table;
  EXPECT_NE(table.find("lobe_naive.frag:23 `float tan2 = (1.0 - nDotH * nDotH) / (nDotH * nDotH);`: OpFSub"),
            std::string::npos)
      << table;
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  fs::remove(json);
  int naive_sharp = 0;
  for (const auto& row : j["rows"]) {
    EXPECT_EQ(row["reference"], "twin-double");
    EXPECT_EQ(row["case"], "gaussian_lobe");
    if (row["variant"] == "pixel_robust") {
      EXPECT_EQ(row["status"], "pass") << row.dump();
    } else if (row["scenario"] == "lobe_sharp") {
      ++naive_sharp;
      EXPECT_EQ(row["status"], "fail") << row.dump();
      ASSERT_TRUE(row["significance_loss"].is_object()) << row.dump();
      EXPECT_EQ(row["significance_loss"]["line"], 23);
      EXPECT_EQ(row["significance_loss"]["operation"], "OpFSub");
      EXPECT_TRUE(row["worst_pixel"].is_array());
    }
  }
  EXPECT_EQ(naive_sharp, 1);
  EXPECT_TRUE(j["scenarios"].contains("gaussian_lobe/lobe_sharp"));
}

TEST(HardCli, MissingUserCaseExitsTwoWithOneLine) {
  const CliRun r = shaderbed("--case no/such/case.toml");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("shaderbed: hard:"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
