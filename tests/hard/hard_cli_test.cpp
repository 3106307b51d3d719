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

}  // namespace
