// Shaders saved with a UTF-8 byte order mark (as Visual Studio saves HLSL; fxc accepts
// it) run to a pass in HLSL and GLSL (issue 30, item 15).
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ShellCommand.h"
#include "SourceTree.h"
#include "TempDir.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

void copy_with_bom(const fs::path& from, const fs::path& to) {
  std::ifstream in(from, std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  fs::create_directories(to.parent_path());
  std::ofstream(to, std::ios::binary) << "\xEF\xBB\xBF" << text;
}

TEST(ShaderBomRun, HlslAndGlslSavedWithAByteOrderMarkRunToAPass) {
  test::TempDir root("shader_bom");
  fs::create_directories(root.path() / "cases");
  fs::copy_file(test::kShaders / "cases" / "lambert.toml", root.path() / "cases" / "lambert.toml");
  for (const char* file : {"hlsl/setup_vs.hlsl", "hlsl/lambert_ps.hlsl", "glsl/setup.vert", "glsl/lambert.frag"})
    copy_with_bom(test::kShaders / file, root.path() / file);
  const std::string json = root / "r.json";
  const auto [status, out] = test::run_shell(std::string(SHADERBED_BINARY) + " run --cases-dir " + root / "cases" +
                                             " --case lambert --variant pixel --lang hlsl,glsl --backend vulkan "
                                             "--shape sphere --size 16 --repeat 0 --quiet --json " + json);
  EXPECT_EQ(status, 0) << out;
  std::ifstream in(json);
  ASSERT_TRUE(in) << out;
  const nlohmann::json report = nlohmann::json::parse(in);
  ASSERT_EQ(report["results"].size(), 2u) << report.dump();
  for (const nlohmann::json& cell : report["results"])
    EXPECT_EQ(cell["status"], "pass") << cell["language"] << ": " << cell["message"];
}

}  // namespace
}  // namespace shaderbed
