// CI-matrix plumbing: shards that add up to the whole run, and known-failure baselines.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "run/CellPlan.h"
#include "run/Expectations.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

TEST(Shard, ParsesAndRejects) {
  auto s = parse_shard("2/5");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->index, 2);
  EXPECT_EQ(s->count, 5);
  for (const char* bad : {"0/3", "4/3", "1/0", "x/2", "1-2", "1/", "/2"}) EXPECT_FALSE(parse_shard(bad)) << bad;
}

TEST(Expectations, PatternsMatchWholeSegments) {
  EXPECT_TRUE(matches("warn/pixel/*/gl/*/torus", "warn/pixel/hlsl/gl/cross/torus"));
  EXPECT_FALSE(matches("warn/pixel/*/gl/*/torus", "warn/pixel/hlsl/vulkan/spirv/torus"));
  EXPECT_TRUE(matches("*/*/*/*/*/*", "a/b/c/d/e/f"));
  EXPECT_TRUE(matches("ward_*/pixel*/glsl/*/*/*", "ward_iso/pixel_lut/glsl/gl/glsl/cone"));
  EXPECT_FALSE(matches("warn/pixel/*/gl/*", "warn/pixel/hlsl/gl/cross/torus")) << "six segments";
  EXPECT_TRUE(matches("a*b*c/*/*/*/*/*", "axxbyybc/v/l/b/p/s")) << "a later star takes over after a mismatch";
  EXPECT_FALSE(matches("a*b*c/*/*/*/*/*", "axxbyybd/v/l/b/p/s"));
  EXPECT_TRUE(matches("**/*/*/*/*/*", "/v/l/b/p/s")) << "stars match the empty run";
  EXPECT_FALSE(matches("?/*/*/*/*/*", "x/v/l/b/p/s")) << "no other wildcard than *";
}

TEST(Expectations, ManyStarsInOneSegmentMatchWithoutBacktrackingBlowUp) {
  // The recursive matcher needed > 30 s for this one failing cell.
  std::string stars;
  for (int i = 0; i < 40; ++i) stars += "*a";
  const std::string pattern = stars + "b/*/*/*/*/*";
  EXPECT_FALSE(matches(pattern, std::string(200, 'a') + "/v/l/b/p/s"));
  EXPECT_TRUE(matches(pattern, std::string(200, 'a') + "b/v/l/b/p/s"));
}

TEST(Expectations, UnknownKeysAreRefusedWithTheNearestOne) {
  const fs::path file = fs::temp_directory_path() / ("shaderbed_known_key_" + std::to_string(::getpid()) + ".toml");
  std::ofstream(file) << "[[known]]\ncells = \"a/b/c/d/e/f\"\nreason = \"r\"\nreasno = \"typo\"\n";
  auto known = load_expectations(file.string());
  fs::remove(file);
  ASSERT_FALSE(known);
  EXPECT_EQ(known.error().line, 4);
  EXPECT_NE(known.error().message.find("did you mean 'reason'?"), std::string::npos) << known.error().to_string();
}

TEST(Expectations, KnownFailureIsReportedAsKnownAndNewOneFails) {
  const fs::path file = fs::temp_directory_path() / ("shaderbed_known_" + std::to_string(::getpid()) + ".toml");
  std::ofstream(file) << "[[known]]\ncells = \"phong/pixel/*/*/*/cube\"\nreason = \"planted in this test\"\n";
  auto known = load_expectations(file.string());
  ASSERT_TRUE(known) << known.error().to_string();
  RunReport report;
  CellResult known_fail{.case_name = "phong", .variant = "pixel", .language = "glsl", .backend = "gl", .path = "glsl",
                        .shape = "cube", .status = CellStatus::fail};
  CellResult new_fail = known_fail;
  new_fail.shape = "torus";
  CellResult now_passes = known_fail;
  now_passes.language = "hlsl";
  now_passes.status = CellStatus::pass;
  report.results = {known_fail, new_fail, now_passes};
  const auto passing = apply_expectations(*known, report);
  EXPECT_TRUE(report.results[0].known_failure);
  EXPECT_EQ(report.results[0].known_reason, "planted in this test");
  EXPECT_FALSE(report.results[1].known_failure);
  EXPECT_FALSE(report.acceptable()) << "the torus failure is new";
  ASSERT_EQ(passing.size(), 1u);
  EXPECT_EQ(passing[0], now_passes.id());
  report.results.erase(report.results.begin() + 1);
  EXPECT_TRUE(report.acceptable());
  fs::remove(file);
}

TEST(Expectations, EntryWithoutReasonIsRefusedWithItsLine) {
  const fs::path file = fs::temp_directory_path() / ("shaderbed_known_bad_" + std::to_string(::getpid()) + ".toml");
  std::ofstream(file) << "# baseline\n[[known]]\ncells = \"a/b/c/d/e/f\"\n";
  auto known = load_expectations(file.string());
  ASSERT_FALSE(known);
  EXPECT_EQ(known.error().line, 2);
  EXPECT_NE(known.error().message.find("reason"), std::string::npos);
  fs::remove(file);
}

}  // namespace
}  // namespace shaderbed
