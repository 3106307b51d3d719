// `shaderbed merge` on shards a user edited or named wrongly (issue 30, items 9 and 12): a
// forged status fails the merge, a shard without a run id is refused, the HTML page reads
// no file outside a shard's own folder, and /dev/zero or a FIFO is one error, not a hang.
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ShellCommand.h"
#include "TempDir.h"

#ifdef SHADERBED_BINARY
namespace shaderbed {
namespace {

namespace fs = std::filesystem;
using test::shaderbed_cli;
using test::TempDir;

nlohmann::json load_results(const std::string& path) { return nlohmann::json::parse(std::ifstream(path)); }
void save_results(const std::string& path, const nlohmann::json& j) { std::ofstream(path) << j.dump(1); }
std::string file_text(const fs::path& path) {
  std::ostringstream s;
  s << std::ifstream(path, std::ios::binary).rdbuf();
  return s.str();
}

// One small real cell, its images under DIR/out and its results in DIR/out/a.json.
std::string one_cell_run(const TempDir& dir) {
  const std::string json = dir / "out/a.json";
  auto [status, out] = shaderbed_cli("run --case lambert --variant pixel --lang glsl --backend vulkan --shape sphere "
                                     "--size 16 --quiet --keep-images all --out " + (dir / "out") + " --json " + json);
  EXPECT_EQ(status, 0) << out;
  return json;
}

TEST(MergeCli, AHandEditedPassFailsTheMergeAndAShardWithoutARunIdIsRefused) {
  TempDir dir("merge_forged");
  const std::string json = one_cell_run(dir);
  ASSERT_EQ(shaderbed_cli("merge " + json).first, 0) << "the honest shard merges";

  nlohmann::json forged = load_results(json);
  nlohmann::json& cell = forged["results"][0];
  cell["status"] = "pass";
  cell["metrics"]["bad_pixels"] = 500;
  cell["metrics"]["max_abs"] = 80;
  cell["metrics"]["nonfinite"] = 7;
  save_results(dir / "forged.json", forged);
  auto [status, out] = shaderbed_cli("merge --quiet " + (dir / "forged.json"));
  EXPECT_EQ(status, 1) << out;
  EXPECT_NE(out.find("lambert/pixel/glsl/vulkan/spirv/sphere: shard said pass; its metrics fail"), std::string::npos) << out;

  for (const bool erase : {true, false}) {
    nlohmann::json anonymous = load_results(json);
    if (erase) anonymous.erase("run_id");
    else anonymous["run_id"] = "";
    save_results(dir / "anonymous.json", anonymous);
    auto [refused, why] = shaderbed_cli("merge " + (dir / "anonymous.json"));
    EXPECT_EQ(refused, 2) << why;
    EXPECT_NE(why.find("shaderbed: " + (dir / "anonymous.json") + ": merge: no run_id"), std::string::npos) << why;
  }
}

TEST(MergeCli, TheHtmlPageReadsNoFileOutsideTheShardsFolder) {
  TempDir dir("merge_artefacts");
  const std::string json = one_cell_run(dir);
  // Files the shard must not make the page embed or copy: a "PNG" and a text outside out/.
  // (9 bytes before the marker, so its base64 is VE9QU0VDUkVU wherever it is encoded.)
  const std::string secret = std::string("\x89PNG\r\n\x1a\nX") + "TOPSECRET-IMAGE-BYTES";
  const std::string png = dir.write("private/secret.png", secret);
  dir.write("private/notes.txt", "TOPSECRET-TEXT");
  nlohmann::json edited = load_results(json);
  nlohmann::json& artefacts = edited["results"][0]["artefacts"];
  const std::string own_render = artefacts["render_png"];
  ASSERT_FALSE(own_render.empty());
  artefacts["error_png"] = png;                                // absolute, outside
  artefacts["vertex_spirv"] = "../private/notes.txt";          // relative, climbing out
  artefacts["fragment_spirv"] = dir / "private/notes.txt";     // absolute, outside
  save_results(dir / "out/a.json", edited);
  // A symlink inside the folder that points out is outside too.
  fs::create_symlink(png, dir / "out/link.png");
  edited["results"][0]["artefacts"]["reference_png"] = (dir / "out/link.png");
  save_results(dir / "out/a.json", edited);

  auto [status, out] = shaderbed_cli("merge --quiet " + json + " --html " + (dir / "report"));
  ASSERT_EQ(status, 0) << out;
  const std::string page = file_text(dir / "report/index.html");
  EXPECT_EQ(page.find("VE9QU0VDUkVU"), std::string::npos) << "base64 of the secret's bytes is in the page";
  EXPECT_EQ(page.find("../private/"), std::string::npos) << "nor linked";
  EXPECT_NE(page.find("4 artefact paths not shown: outside the folder of the results file"), std::string::npos);
  for (const auto& entry : fs::recursive_directory_iterator(dir / "report"))
    if (entry.is_regular_file()) {
      EXPECT_EQ(file_text(entry.path()).find("TOPSECRET-TEXT"), std::string::npos) << entry.path();
    }
  EXPECT_NE(page.find("data:image/png;base64,"), std::string::npos) << "the shard's own render is still embedded";
}

// /dev/zero or a FIFO named as a results file or a chart: one line naming it, exit 2, at once.
TEST(MergeCli, ADeviceOrAFifoIsOneErrorNamingIt) {
  TempDir dir("merge_fifo");
  const std::string fifo = dir / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string valid = dir.write("valid.json", "{}");
  for (const std::string& args : {std::string("merge /dev/zero"), "merge " + fifo, "merge --chart /dev/zero " + valid,
                                  "merge --chart " + fifo + " " + valid, std::string("run --chart /dev/zero --case lambert"),
                                  "run --chart " + fifo + " --case lambert"}) {
    // (Bounded, should it ever read /dev/zero again: this machine is shared.)
    auto [status, out] = test::run_shell("ulimit -v 4000000; timeout 10 " + std::string(SHADERBED_BINARY) + " " + args);
    EXPECT_EQ(status, 2) << args << "\n" << out;
    const std::string named = args.find("/dev/zero") != std::string::npos ? "/dev/zero" : fifo;
    EXPECT_NE(out.find("shaderbed: " + named + ": "), std::string::npos) << args << "\n" << out;
    EXPECT_NE(out.find("not a regular file"), std::string::npos) << args << "\n" << out;
  }
}

TEST(MergeCli, AFieldOfTheWrongTypeIsOneErrorNamingIt) {
  TempDir dir("merge_types");
  for (const char* text : {R"({"schema": 2, "run_id": "r", "results": [{"case": 1}]})",
                           R"({"schema": 2, "run_id": 7, "results": []})",
                           R"({"schema": 2, "run_id": "r", "results": {"a": 1}})"}) {
    const std::string file = dir.write("typed.json", text);
    auto [status, out] = shaderbed_cli("merge " + file);
    EXPECT_EQ(status, 2) << text << "\n" << out;
    EXPECT_EQ(out.rfind("shaderbed: " + file + ": ", 0), 0u) << text << "\n" << out;
  }
}

}  // namespace
}  // namespace shaderbed
#endif
