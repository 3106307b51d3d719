// Shaders as their authors wrote them (tests/realworld/): each runs unchanged through the
// runner on every path that takes it, with only a case file written next to it.
#include <filesystem>
#include <fstream>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "RealWorldRuns.h"
#include "run/Runner.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;
using test::kRealWorld;

TEST(RealShaders, OneFileWithNamedEntryPointsPassesOnEveryHlslPath) {
  RunOptions o;
  o.select.cases_dir = (kRealWorld / "cases").string();
  o.select.cases = {"hlsl_lambert_two_entries"};
  o.cell.size = 64;
  o.cell.timing = {.warmup = 0, .runs = 0};
  auto report = run_suite(o);
  ASSERT_TRUE(report) << report.error().to_string();
  const std::set<std::string> paths = test::paths_all_with_status(*report, "pass");
  EXPECT_EQ(paths, (std::set<std::string>{"vulkan/spirv", "gl/spirv", "gl/cross"}));
  EXPECT_EQ(report->results.size(), 12u);
}

// The corpus's hlsl_lambert_two_entries case with `edit` applied (each pair: text to find, its
// replacement), run on the sphere at 32 px.
Result<RunReport> run_edited_case(const std::vector<std::pair<std::string, std::string>>& edits) {
  const fs::path root = fs::temp_directory_path() / ("shaderbed_realworld_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "cases");
  fs::create_directory_symlink(kRealWorld / "hlsl", root / "hlsl");
  std::ifstream in(kRealWorld / "cases" / "hlsl_lambert_two_entries.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const auto& [from, to] : edits) {
    EXPECT_NE(text.find(from), std::string::npos) << from;
    if (text.find(from) != std::string::npos) text.replace(text.find(from), from.size(), to);
  }
  std::ofstream(root / "cases" / "hlsl_lambert_two_entries.toml") << text;
  RunOptions o;
  o.select.cases_dir = (root / "cases").string();
  o.cell.size = 32;
  o.select.shapes = {"sphere"};
  o.cell.timing = {.warmup = 0, .runs = 0};
  auto report = run_suite(o);
  fs::remove_all(root);
  return report;
}

TEST(RealShaders, EveryUnboundUniformIsListedInOneError) {
  auto report = run_edited_case({{"WorldViewProj = \"transform\"\n", ""}, {"MaterialDiffuse = \"diffuse\"\n", ""}});
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_FALSE(report->results.empty());
  for (const CellResult& r : report->results) {
    EXPECT_EQ(r.status, CellStatus::error) << r.id();
    EXPECT_NE(r.message.find("2 uniforms cannot be bound"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("'WorldViewProj'"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("'MaterialDiffuse'"), std::string::npos) << r.message;
  }
}

TEST(RealShaders, AnEntryPointTheFileDoesNotHaveIsAnErrorNamingIt) {
  // The same shader and case, with the pixel stage's entry misspelt.
  auto report = run_edited_case({{"fragment_entry = \"LightPixelShader\"", "fragment_entry = \"LightPixelShder\""}});
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_FALSE(report->results.empty());
  for (const CellResult& r : report->results) {
    EXPECT_EQ(r.status, CellStatus::error) << r.id();
    EXPECT_NE(r.message.find("LightPixelShder"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("lambert_two_entries.hlsl"), std::string::npos) << r.message;
  }
}

}  // namespace
}  // namespace shaderbed
