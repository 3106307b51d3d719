// Reports are written whole or not at all: through a temporary file renamed over the
// target, so a reader never sees half a report and a failed write keeps the old one.
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

TEST(AtomicFile, AFailedWriteKeepsTheOldFile) {
  test::TempDir dir("atomic_fail");
  const fs::path file = dir.path() / "results.json";
  ASSERT_TRUE(write_file_atomically(file.string(), "old\n", "test file"));
  // A folder where the temporary file would go: the write cannot even start.
  fs::create_directory(file.string() + ".tmp." + std::to_string(::getpid()));
  auto failed = write_file_atomically(file.string(), "new\n", "test file");
  EXPECT_FALSE(failed);
  EXPECT_EQ(read(file), "old\n");
}

}  // namespace
}  // namespace shaderbed
