// An output is never one of the command's inputs (issue 30, item 6): `run --json CASE.toml`,
// `--junit SHADER`, `--html` into the shaders' folder, `init x.hlsl --out x.hlsl --force`
// and `init x.toml --force` are refused before anything is written, and the input is
// left byte for byte as it was.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "CopiedCase.h"
#include "FileContents.h"
#include "ShellCommand.h"
#include "TempDir.h"

namespace {

namespace fs = std::filesystem;
using shaderbed::test::copy_blinn_phong_case;
using shaderbed::test::read_text;
using shaderbed::test::shaderbed_cli;
using shaderbed::test::TempDir;

// The command is refused as bad input naming the option, and `input` is unchanged.
void expect_refused(const std::string& args, const fs::path& input, const std::string& option) {
  const std::string before = read_text(input);
  const auto [status, out] = shaderbed_cli(args);
  EXPECT_EQ(status, 2) << out;
  EXPECT_NE(out.find(option + ": '"), std::string::npos) << out;
  EXPECT_NE(out.find("writing it would destroy it"), std::string::npos) << out;
  EXPECT_EQ(out.find("cells"), std::string::npos) << "refused before anything was drawn:\n" << out;
  EXPECT_EQ(read_text(input), before);
}

TEST(OutputsNotInputs, RunRefusesJsonOverItsCaseFile) {
  TempDir dir("out_in_case");
  const fs::path c = copy_blinn_phong_case(dir.path());
  expect_refused("run --case " + c.string() + " --backend vulkan --shape sphere --size 16 --repeat 0 --json " +
                     (dir / "cases/../cases/blinn.toml"),
                 c, "--json");
}

TEST(OutputsNotInputs, RunRefusesJunitOverAShaderThroughASymlink) {
  TempDir dir("out_in_shader");
  const fs::path c = copy_blinn_phong_case(dir.path());
  fs::create_symlink(dir / "glsl330/blinn_phong.frag", dir / "report.xml");
  expect_refused("run --case " + c.string() + " --backend vulkan --shape sphere --size 16 --repeat 0 --junit " +
                     (dir / "report.xml"),
                 dir / "glsl330/blinn_phong.frag", "--junit");
}

TEST(OutputsNotInputs, InitRefusesItsShaderAsTheCase) {
  TempDir dir("out_in_init");
  fs::copy(fs::path(SHADERBED_SOURCE_DIR) / "tests/realworld/glsl330", dir / "glsl330", fs::copy_options::recursive);
  const fs::path frag = dir / "glsl330/blinn_phong.frag";
  expect_refused("init " + (dir / "glsl330/blinn_phong.vert") + " " + frag.string() + " --out " +
                     frag.string() + " --force",
                 frag, "--out");
  // A shader whose name ends in .toml would be its own default case file.
  fs::copy_file(frag, dir / "glsl330/light.toml");
  expect_refused("init " + (dir / "glsl330/light.toml") + " --lang glsl --force", dir / "glsl330/light.toml",
                 "--out");
}

TEST(OutputsNotInputs, MergeAndStatsRefuseToWriteOverWhatTheyRead) {
  TempDir dir("out_in_merge");
  const fs::path c = copy_blinn_phong_case(dir.path());
  const std::string shard = dir / "shard.json";
  ASSERT_EQ(shaderbed_cli("run --case " + c.string() + " --backend vulkan --shape sphere --size 16 --repeat 0 --json " +
                          shard).first, 0);
  expect_refused("merge " + shard + " --json " + shard, shard, "--json");
  const std::string counts = dir / "counts.json";
  ASSERT_EQ(shaderbed_cli("stats --cases-dir " + (dir / "cases") + " --no-nir --json " + counts).first, 0);
  expect_refused("stats --from " + counts + " --baseline " + counts + " --json " + counts, counts, "--json");
}

}  // namespace
