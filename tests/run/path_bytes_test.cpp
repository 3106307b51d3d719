// Paths are bytes (issue 30, item 15): a case folder and an --out folder whose names are
// not UTF-8 (Latin-1, as an old archive unpacks) reach the isolated workers unchanged, so
// the cells pass and the images land in the folder the user named; and a --json name near
// NAME_MAX is written, or refused before the run when it is over.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "CopiedCase.h"
#include "ShellCommand.h"
#include "TempDir.h"

namespace {

namespace fs = std::filesystem;
using shaderbed::test::copy_blinn_phong_case;
using shaderbed::test::shaderbed_cli;
using shaderbed::test::TempDir;

TEST(PathBytes, LatinOneFoldersReachTheWorkers) {
  TempDir dir("path_bytes");
  const fs::path root = dir.path() / "caf\xe9";   // "café" in Latin-1: not UTF-8
  copy_blinn_phong_case(root);
  const fs::path out = dir.path() / "r\xe9sultats";
  const auto [status, text] = shaderbed_cli("run --cases-dir '" + (root / "cases").string() +
                                             "' --backend vulkan --shape sphere --size 16 --repeat 0 --keep-images all --out '" +
                                             out.string() + "'");
  EXPECT_EQ(status, 0) << text;
  EXPECT_NE(text.find("1 passed"), std::string::npos) << text;
  EXPECT_TRUE(fs::exists(out / "blinn/pixel/sphere/glsl-vulkan-spirv.exr")) << text;
}

TEST(PathBytes, LongJsonNamesAreWrittenOrRefusedUpFront) {
  TempDir dir("long_json");
  const fs::path c = copy_blinn_phong_case(dir.path());
  const std::string args = "run --case " + c.string() + " --backend vulkan --shape sphere --size 16 --repeat 0 --json ";
  // 250 characters: the name fits NAME_MAX (255), its temporary sibling must too.
  const fs::path fits = dir.path() / (std::string(245, 'r') + ".json");
  auto [status, text] = shaderbed_cli(args + fits.string());
  EXPECT_EQ(status, 0) << text;
  EXPECT_TRUE(fs::exists(fits)) << text;
  const fs::path over = dir.path() / (std::string(260, 'r') + ".json");
  std::tie(status, text) = shaderbed_cli(args + over.string());
  EXPECT_EQ(status, 2) << text;
  EXPECT_NE(text.find("--json"), std::string::npos) << text;
  EXPECT_EQ(text.find("cells"), std::string::npos) << "refused before the run:\n" << text;
}

}  // namespace
