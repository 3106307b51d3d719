// A [bindings.<lang>] entry naming a uniform (or register) no shader of the case declares
// is a warning on the cell, not an error: the cell still runs and passes, and the warning
// reaches the console, the JSON and JUnit. An entry another variant reads is no warning.
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ShellCommand.h"
namespace {

namespace fs = std::filesystem;

TEST(UnusedBinding, IsAWarningOnAPassingCell) {
  const fs::path dir = fs::temp_directory_path() / ("unused_binding_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // The library's Lambert case plus two bindings nothing declares.
  std::ifstream in(fs::path(SHADERBED_SOURCE_DIR) / "shaders/cases/lambert.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string glsl = "[bindings.glsl]\n", hlsl = "[bindings.hlsl]\n";
  ASSERT_NE(text.find(glsl), std::string::npos);
  ASSERT_NE(text.find(hlsl), std::string::npos);
  text.insert(text.find(glsl) + glsl.size(), "specularPower = 7.0\n");
  text.insert(text.find(hlsl) + hlsl.size(), "c12 = [0.0, 0.0, 0.0, 0.0]\n");
  // Written outside the source tree, its shaders named by absolute path.
  for (const char* language : {"hlsl", "glsl", "cg"})
    for (size_t at; (at = text.find(std::string("\"") + language + "/")) != std::string::npos;)
      text.replace(at + 1, 0, (fs::path(SHADERBED_SOURCE_DIR) / "shaders").string() + "/");
  const fs::path case_file = dir / "unused_binding.toml";
  { std::ofstream(case_file) << text; }
  const fs::path json = dir / "r.json", junit = dir / "r.xml";
  const auto [status, out] = shaderbed::test::run_shell(
      std::string(SHADERBED_BINARY) + " run --case " + case_file.string() +
      " --lang glsl,hlsl --backend vulkan --shape sphere --size 32 --repeat 0 --quiet --json " +
      json.string() + " --junit " + junit.string());
  fs::remove(case_file);
  EXPECT_EQ(status, 0) << "a warning does not fail the run:\n" << out;
  EXPECT_NE(out.find("warnings:"), std::string::npos) << out;
  EXPECT_NE(out.find("binding 'specularPower'"), std::string::npos) << out;
  EXPECT_NE(out.find("binding 'c12' names a register"), std::string::npos) << out;

  std::ifstream j(json);
  const nlohmann::json results = nlohmann::json::parse(j)["results"];
  ASSERT_EQ(results.size(), 4u) << "vertex and pixel variants: a run of every variant can tell what none declares";
  for (const auto& cell : results) {
    EXPECT_EQ(cell["status"], "pass") << cell.dump();
    ASSERT_EQ(cell["warnings"].size(), 1u) << cell.dump();
    EXPECT_NE(cell["warnings"][0].get<std::string>().find(cell["language"] == "glsl" ? "specularPower" : "c12"),
              std::string::npos);
  }
  std::ifstream x(junit);
  const std::string xml((std::istreambuf_iterator<char>(x)), std::istreambuf_iterator<char>());
  EXPECT_NE(xml.find("warning: line"), std::string::npos) << xml;
  fs::remove_all(dir);
}

TEST(UnusedBinding, LibraryCasesHaveNone) {
  // One table per language serves every variant: what only the vertex shader reads is used.
  const auto [status, out] = shaderbed::test::run_shell(std::string(SHADERBED_BINARY) +
                                                        " run --case phong,warn,ward_iso --shape cube --backend vulkan "
                                                        "--size 16 --repeat 0 --quiet");
  EXPECT_EQ(status, 0) << out;
  EXPECT_EQ(out.find("warnings:"), std::string::npos) << out;
}

}  // namespace
