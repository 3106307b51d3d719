// A cache root that cannot take writes: the run goes on without Mesa's shader cache and
// without compile-cache writes, and one note on stderr says so (issue 30, item 10). The
// full-disk case (a 2 MiB tmpfs, which needs root) is tests/reliability/full_cache_disk.sh.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ShellCommand.h"
#include "TempDir.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

size_t occurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(CacheFolderRun, AnUnusableCacheRootMeansNoCachesAndOneNoteNotACrash) {
  test::TempDir work("cache_folder_run");
  const std::string blocker = work.write("blocker", "a file where the cache root's parent should be");
  const std::string root = blocker + "/cache";
  const std::string json = work / "r.json";
  const auto [status, out] = test::run_shell(
      "env -u MESA_SHADER_CACHE_DIR -u MESA_SHADER_CACHE_DISABLE -u MESA_GLSL_CACHE_DIR -u MESA_GLSL_CACHE_DISABLE "
      "-u SHADERBED_MESA_SHADER_CACHE -u SHADERBED_CACHE_FOLDER_NOTED SHADERBED_CACHE_DIR='" + root + "' " +
      SHADERBED_BINARY +
      " run --case lambert --variant pixel --lang glsl --backend vulkan,gl --shape sphere --size 16 --repeat 0 "
      "--quiet --json " + json);
  EXPECT_EQ(status, 0) << out;
  EXPECT_EQ(occurrences(out, "shaderbed: note: the cache folder " + root), 1u) << out;
  EXPECT_NE(out.find("running without Mesa's shader cache"), std::string::npos) << out;
  std::ifstream in(json);
  ASSERT_TRUE(in) << out;
  const nlohmann::json report = nlohmann::json::parse(in);
  ASSERT_EQ(report["results"].size(), 4u) << "vulkan/spirv and GL's spirv, glsl and cross paths";
  for (const nlohmann::json& cell : report["results"]) EXPECT_EQ(cell["status"], "pass") << cell.dump();
  EXPECT_EQ(report["cache"]["driver"]["enabled"], false) << report["cache"].dump();
}

}  // namespace
}  // namespace shaderbed
