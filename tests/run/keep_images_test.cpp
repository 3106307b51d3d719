// Lean output (issue 29, item 2): --out keeps the images of the cells that did not pass
// and the references they are judged against, not a green run's hundreds of renders;
// --keep-images all keeps every cell's, none keeps none; the HTML page says which.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "FileContents.h"
#include "ShellCommand.h"
#include "TempDir.h"

namespace {

namespace fs = std::filesystem;
using shaderbed::test::read_text;
using shaderbed::test::shaderbed_cli;
using shaderbed::test::TempDir;

size_t images_under(const fs::path& dir) {
  size_t n = 0;
  if (fs::exists(dir))
    for (const auto& e : fs::recursive_directory_iterator(dir))
      n += e.path().extension() == ".png" || e.path().extension() == ".exr";
  return n;
}

// The real-world port with a planted bug fails on its sphere; lambert passes.
std::string run_args(const TempDir& dir, const std::string& keep) {
  return "run --cases-dir " + std::string(SHADERBED_SOURCE_DIR) + "/tests/realworld/cases --case glsl330_blinn_phong_bug "
         "--backend vulkan --shape sphere --size 24 --repeat 0 --out " + dir / "out" + " --html " + dir / "html" +
         " --json " + dir / "r.json" + (keep.empty() ? "" : " --keep-images " + keep);
}

TEST(KeepImages, ByDefaultOnlyWhatDidNotPassIsKept) {
  TempDir dir("keep_failing");
  const auto [status, out] = shaderbed_cli(run_args(dir, ""));
  ASSERT_EQ(status, 1) << out;
  const auto report = nlohmann::json::parse(read_text(dir / "r.json"));
  size_t failing = 0;
  for (const auto& cell : report["results"]) {
    const std::string render = cell["artefacts"]["render_png"];
    if (cell["status"] == "pass") {
      EXPECT_TRUE(render.empty()) << cell["id"];
    } else {
      ++failing;
      EXPECT_TRUE(fs::exists(render)) << cell["id"];
      EXPECT_TRUE(fs::exists(std::string(cell["artefacts"]["reference_png"]))) << cell["id"];
    }
  }
  ASSERT_GT(failing, 0u);
  // Per failing cell: render and error as EXR and PNG; and the references it was judged against.
  EXPECT_GE(images_under(dir / "out"), 4 * failing);
  EXPECT_EQ(report["keep_images"], "failing");
  EXPECT_NE(read_text(dir / "html/index.html").find("kept the images of the cells that did not pass only"),
            std::string::npos);
}

TEST(KeepImages, AllKeepsEveryCellsAndNoneKeepsNone) {
  TempDir all("keep_all"), none("keep_none");
  ASSERT_EQ(shaderbed_cli(run_args(all, "all")).first, 1);
  ASSERT_EQ(shaderbed_cli(run_args(none, "none")).first, 1);
  const auto report = nlohmann::json::parse(read_text(all / "r.json"));
  for (const auto& cell : report["results"])
    EXPECT_TRUE(fs::exists(std::string(cell["artefacts"]["render_png"]))) << cell["id"];
  EXPECT_EQ(images_under(none / "out"), 0u);
  EXPECT_NE(read_text(none / "html/index.html").find("kept no images"), std::string::npos);
}

}  // namespace
