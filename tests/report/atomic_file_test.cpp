// Reports are written whole or not at all: through a temporary file renamed over the
// target, so a reader never sees half a report and a failed write keeps the old one.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "TempDir.h"
#include "core/AtomicFile.h"
#include "report/JsonReport.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(AtomicFile, ReplacesTheFileAndLeavesNoTemporary) {
  test::TempDir dir("atomic");
  const fs::path file = dir.path() / "out" / "results.json";
  ASSERT_TRUE(write_file_atomically(file.string(), "old\n", "test file"));
  ASSERT_TRUE(write_json(RunReport{}, file.string()));
  EXPECT_NE(read(file).find("\"results\""), std::string::npos);
  size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(file.parent_path())) ++entries;
  EXPECT_EQ(entries, 1u) << "no temporary file stays behind";
}

TEST(AtomicFile, AFailedWriteKeepsWhatWasThereAndLeavesNoTemporary) {
  test::TempDir dir("atomic_fail");
  // A folder with a file in it where the report would go: the rename over it fails.
  const fs::path file = dir.path() / "results.json";
  fs::create_directories(file);
  std::ofstream(file / "kept") << "kept\n";
  auto failed = write_file_atomically(file.string(), "new\n", "test file");
  EXPECT_FALSE(failed);
  EXPECT_EQ(read(file / "kept"), "kept\n");
  size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 1u) << "no temporary file stays behind";
}

// Issue 30: a symlink planted where the temporary file used to go (PATH.tmp.<pid>) made the
// report overwrite the file it pointed to, and PATH became the symlink.
TEST(AtomicFile, APlantedSymlinkIsNeverFollowed) {
  test::TempDir dir("atomic_symlink");
  const fs::path victim = dir.path() / "victim.txt";
  std::ofstream(victim) << "precious\n";
  const fs::path file = dir.path() / "results.json";
  fs::create_symlink(victim, file.string() + ".tmp." + std::to_string(::getpid()));
  ASSERT_TRUE(write_file_atomically(file.string(), "new\n", "test file"));
  EXPECT_EQ(read(victim), "precious\n");
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(file)));
  EXPECT_EQ(read(file), "new\n");
  // A symlink at the target itself is replaced, not written through.
  const fs::path linked = dir.path() / "linked.json";
  fs::create_symlink(victim, linked);
  ASSERT_TRUE(write_file_atomically(linked.string(), "report\n", "test file"));
  EXPECT_EQ(read(victim), "precious\n");
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(linked)));
}

TEST(AtomicFile, TheFileIsReadableAsFopenWouldMakeIt) {
  test::TempDir dir("atomic_mode");
  const fs::path file = dir.path() / "results.json";
  ASSERT_TRUE(write_file_atomically(file.string(), "x\n", "test file"));
  const mode_t mask = ::umask(0);
  ::umask(mask);
  EXPECT_EQ(fs::status(file).permissions(), fs::perms(0666 & ~mask));
}

}  // namespace
}  // namespace shaderbed
