// A cache folder that cannot take writes (it cannot be created, its disk is nearly full,
// a write fails) is found before Mesa maps an index in it: cache_folder_problem on real
// paths, and a compile cache that is only read then (issue 30, item 10).
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "TempDir.h"
#include "compile/CompileCache.h"
#include "core/CacheSettings.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

TEST(CacheFolder, AWritableFolderWithRoomHasNoProblemAndNoProbeLeftBehind) {
  test::TempDir dir("cache_folder");
  EXPECT_EQ(cache_folder_problem((dir.path() / "root").string()), "");
  EXPECT_TRUE(fs::is_directory(dir.path() / "root")) << "created";
  EXPECT_TRUE(fs::is_empty(dir.path() / "root")) << "the probe file is removed";
}

TEST(CacheFolder, AFolderThatCannotBeCreatedIsAProblem) {
  test::TempDir dir("cache_folder");
  const std::string file = dir.write("file", "not a folder");
  EXPECT_NE(cache_folder_problem(file + "/root").find("cannot be created"), std::string::npos);
}

TEST(CacheFolder, TooLittleFreeSpaceIsAProblem) {
  test::TempDir dir("cache_folder");
  // The real filesystem's free space, against a margin no disk has.
  const std::string problem = cache_folder_problem(dir.path().string(), std::numeric_limits<uint64_t>::max() / 2);
  EXPECT_NE(problem.find("free"), std::string::npos) << problem;
}

TEST(CacheFolder, AFolderWithoutWritePermissionIsAProblemUnlessRootWritesAnyway) {
  test::TempDir dir("cache_folder");
  const fs::path locked = dir.path() / "locked";
  fs::create_directories(locked);
  ASSERT_EQ(::chmod(locked.c_str(), 0500), 0);
  const std::string problem = cache_folder_problem(locked.string());
  ::chmod(locked.c_str(), 0700);
  if (::geteuid() == 0)
    EXPECT_EQ(problem, "") << "root's writes succeed: the probe, not the mode bits, decides";
  else
    EXPECT_NE(problem.find("not writable"), std::string::npos) << problem;
}

TEST(CacheFolder, AReadOnlyCompileCacheServesEntriesButWritesNone) {
  test::TempDir dir("cache_folder");
  CompileToolchain toolchain = current_compile_toolchain();
  toolchain.stage_code = "cache_folder_test";
  const ShaderSource src{.stage = Stage::fragment,
                         .path = "ro.frag",
                         .text = "#version 450\nlayout(location = 0) out vec4 c;\nvoid main() { c = vec4(1.0); }\n",
                         .entry_point = "main"};
  CompileCache read_only(dir.path(), toolchain, /*writes=*/false);
  ASSERT_TRUE(read_only.stage(Language::glsl, src, Target::vulkan));
  EXPECT_TRUE(fs::is_empty(dir.path())) << "nothing written";
  CompileCache writer(dir.path(), toolchain);
  ASSERT_TRUE(writer.stage(Language::glsl, src, Target::vulkan));
  EXPECT_TRUE(read_only.find_stage(Language::glsl, src, Target::vulkan)) << "entries others wrote are still read";
}

}  // namespace
}  // namespace shaderbed
