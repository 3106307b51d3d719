// merge: the shards of one run join into one report; shards of different runs, or without
// a run id, are refused, a missing or interrupted shard leaves the merged report incomplete,
// and each cell is judged again from its metrics, so an edited status cannot pass.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "report/ShardMerge.h"

namespace shaderbed {
namespace {

RunReport shard(const std::string& run_id, const std::string& which, const std::string& shape) {
  RunReport r;
  r.run_id = run_id;
  r.shard = which;
  CellResult cell{.case_name = "lambert", .variant = "pixel", .language = "glsl", .backend = "vulkan", .path = "spirv",
                  .shape = shape, .status = CellStatus::pass};
  // A pass as a run writes it: within its tolerance, every pixel where the reference has it.
  cell.interior_threshold = 1e-3;
  cell.silhouette_threshold = 2e-3;
  cell.metrics.max_abs = 2e-4;
  cell.metrics.silhouette_max_abs = 5e-4;
  cell.metrics.tolerance_share = 0.2;
  cell.metrics.interior_pixels = 300;
  cell.metrics.silhouette_pixels = 80;
  cell.metrics.covered_pixels = cell.metrics.reference_covered_pixels = 340;
  cell.metrics.expected_area = 338.5;
  r.results.push_back(cell);
  return r;
}

TEST(ShardMerge, ShardsOfOneRunJoinInTheCanonicalOrder) {
  auto merged = merge_shards({shard("abc", "2/2", "sphere"), shard("abc", "1/2", "cube")}, {"b.json", "a.json"});
  ASSERT_TRUE(merged) << merged.error().to_string();
  ASSERT_EQ(merged->results.size(), 2u);
  EXPECT_EQ(merged->results[0].shape, "cube");
  EXPECT_EQ(merged->run_id, "abc");
  EXPECT_FALSE(merged->interruption);
  EXPECT_TRUE(merged->acceptable());
}

TEST(ShardMerge, ShardsOfDifferentRunsAreRefused) {
  auto merged = merge_shards({shard("abc", "1/2", "cube"), shard("def", "2/2", "sphere")}, {"a.json", "b.json"});
  ASSERT_FALSE(merged);
  EXPECT_NE(merged.error().message.find("run def is not the run of the files before it (abc)"), std::string::npos)
      << merged.error().to_string();
  EXPECT_EQ(merged.error().file, "b.json");
}

TEST(ShardMerge, AMissingShardLeavesTheReportIncomplete) {
  auto merged = merge_shards({shard("abc", "1/3", "cube"), shard("abc", "3/3", "sphere")}, {"a.json", "c.json"});
  ASSERT_TRUE(merged);
  ASSERT_TRUE(merged->interruption);
  EXPECT_EQ(merged->interruption->reason, "shard 2/3 missing");
  EXPECT_FALSE(merged->acceptable());
}

TEST(ShardMerge, ASecondCopyOfAShardOrACellIsRefused) {
  auto twice = merge_shards({shard("abc", "1/2", "cube"), shard("abc", "1/2", "sphere")}, {"a.json", "b.json"});
  ASSERT_FALSE(twice);
  EXPECT_NE(twice.error().message.find("shard 1/2 is also in a.json"), std::string::npos);
  auto cell = merge_shards({shard("abc", "", "cube"), shard("abc", "", "cube")}, {"a.json", "b.json"});
  ASSERT_FALSE(cell);
  EXPECT_NE(cell.error().message.find("is already in an earlier file"), std::string::npos);
}

TEST(ShardMerge, AnInterruptedShardIsNamed) {
  RunReport cut = shard("abc", "2/2", "sphere");
  cut.interruption = Interruption{2, "interrupted by SIGINT after 1 of 9 cells"};
  auto merged = merge_shards({shard("abc", "1/2", "cube"), cut}, {"a.json", "b.json"});
  ASSERT_TRUE(merged);
  ASSERT_TRUE(merged->interruption);
  EXPECT_EQ(merged->interruption->reason, "b.json: interrupted by SIGINT after 1 of 9 cells");
}

TEST(ShardMerge, JobsOfAMatrixJoinWhenTheyReadTheSameCaseFilesWithTheSameToolchain) {
  RunReport vulkan = shard("abc", "", "sphere"), gl = shard("abc", "", "sphere");
  gl.results[0].backend = "gl";
  vulkan.case_digests = gl.case_digests = {{"lambert", "d1"}};
  vulkan.tools.vulkan_driver = "Mesa 22.3.6";   // a GL-only job knows no Vulkan driver
  gl.tools.gl_driver = "Mesa 22.3.6";
  auto merged = merge_shards({vulkan, gl}, {"vulkan.json", "gl.json"});
  ASSERT_TRUE(merged) << merged.error().to_string();
  EXPECT_EQ(merged->results.size(), 2u);
  EXPECT_EQ(merged->tools.vulkan_driver, "Mesa 22.3.6");
  EXPECT_EQ(merged->tools.gl_driver, "Mesa 22.3.6");

  RunReport edited = gl;
  edited.case_digests = {{"lambert", "d2"}};
  auto other_file = merge_shards({vulkan, edited}, {"vulkan.json", "gl.json"});
  ASSERT_FALSE(other_file);
  EXPECT_NE(other_file.error().message.find("case lambert was read from another case file"), std::string::npos)
      << other_file.error().to_string();

  RunReport newer = gl;
  newer.tools.gl_driver = "Mesa 24.0.0";
  vulkan.tools.gl_driver = "Mesa 22.3.6";
  auto other_driver = merge_shards({vulkan, newer}, {"vulkan.json", "gl.json"});
  ASSERT_FALSE(other_driver);
  EXPECT_NE(other_driver.error().message.find("another toolchain: the GL driver is Mesa 24.0.0"), std::string::npos)
      << other_driver.error().to_string();
}

TEST(ShardMerge, AShardWithoutARunIdIsRefused) {
  auto merged = merge_shards({shard("abc", "1/2", "cube"), shard("", "2/2", "sphere")}, {"a.json", "b.json"});
  ASSERT_FALSE(merged);
  EXPECT_EQ(merged.error().file, "b.json");
  EXPECT_NE(merged.error().message.find("no run_id"), std::string::npos) << merged.error().to_string();
  EXPECT_FALSE(merge_shards({shard("", "", "cube")}, {"only.json"})) << "nor may a file alone have none";
}

TEST(ShardMerge, APassWhoseMetricsFailIsAFailureThatSaysSo) {
  // The hand edit of issue 30: status pass, 500 bad pixels, max_abs 80, 7 non-finite pixels.
  RunReport forged = shard("abc", "2/2", "sphere");
  CellMetrics& m = forged.results[0].metrics;
  m.bad_pixels = 500;
  m.max_abs = 80;
  m.nonfinite = 7;
  std::vector<std::string> rejudged;
  auto merged = merge_shards({shard("abc", "1/2", "cube"), forged}, {"a.json", "b.json"}, &rejudged);
  ASSERT_TRUE(merged) << merged.error().to_string();
  const CellResult& cell = merged->results[1];
  EXPECT_EQ(cell.shape, "sphere");
  EXPECT_EQ(cell.status, CellStatus::fail);
  EXPECT_NE(cell.message.find("shard said pass; its metrics fail: interior max 80 over 0.001"), std::string::npos)
      << cell.message;
  EXPECT_NE(cell.message.find("500 bad pixels"), std::string::npos) << cell.message;
  ASSERT_EQ(rejudged.size(), 1u);
  EXPECT_EQ(rejudged[0].rfind("b.json: lambert/pixel/glsl/vulkan/spirv/sphere: shard said pass", 0), 0u) << rejudged[0];
  EXPECT_EQ(merged->results[0].status, CellStatus::pass) << "the honest shard's cell stays as it was";
  EXPECT_FALSE(merged->acceptable());
}

TEST(ShardMerge, EachCheckOfTheRunIsMadeAgain) {
  const auto rejudged_status = [](auto edit) {
    RunReport part = shard("abc", "", "cube");
    edit(part.results[0]);
    auto merged = merge_shards({part}, {"a.json"});
    EXPECT_TRUE(merged) << merged.error().to_string();
    return merged ? merged->results[0].status : CellStatus::error;
  };
  EXPECT_EQ(rejudged_status([](CellResult&) {}), CellStatus::pass);
  EXPECT_EQ(rejudged_status([](CellResult& r) { r.metrics.bad_pixels = 1; }), CellStatus::fail);
  EXPECT_EQ(rejudged_status([](CellResult& r) { r.metrics.nonfinite_mismatch = 1; }), CellStatus::fail);
  EXPECT_EQ(rejudged_status([](CellResult& r) { r.metrics.coverage_mismatch = 3; }), CellStatus::fail);
  EXPECT_EQ(rejudged_status([](CellResult& r) { r.metrics.covered_pixels = 0; }), CellStatus::fail) << "blank";
  EXPECT_EQ(rejudged_status([](CellResult& r) { r.metrics.covered_pixels = 300; }), CellStatus::fail) << "off the area";
  EXPECT_EQ(rejudged_status([](CellResult& r) { r.metrics = {}; }), CellStatus::fail) << "metrics removed";
  EXPECT_EQ(rejudged_status([](CellResult& r) { r.metrics.silhouette_max_abs = 0.5; }), CellStatus::fail);
  EXPECT_EQ(rejudged_status([](CellResult& r) { r.metrics.max_abs = NAN; }), CellStatus::fail);
  EXPECT_EQ(rejudged_status([](CellResult& r) { r.metrics.tolerance_share = 1.5; }), CellStatus::fail);
  // With a relative tolerance the maximum alone is no verdict (|reference| is not kept): the share is.
  EXPECT_EQ(rejudged_status([](CellResult& r) { r.interior_threshold_rel = 1e-2, r.metrics.max_abs = 5e-3; }),
            CellStatus::pass);
  EXPECT_EQ(rejudged_status([](CellResult& r) {
              r.sh = CellResult::ShErrors{.truncation = 0.2, .bound = 0.1};
            }),
            CellStatus::fail)
      << "an SH approximation over its bound";
  EXPECT_EQ(rejudged_status([](CellResult& r) { r.sh = CellResult::ShErrors{.truncation = 0.05, .bound = 0.1}; }),
            CellStatus::pass);
}

TEST(ShardMerge, FailuresErrorsAndSkipsKeepTheirMeaningWhenTheirMetricsAgree) {
  RunReport part = shard("abc", "", "cube");
  CellResult fail = part.results[0], known = part.results[0], error = part.results[0], skipped = part.results[0];
  fail.shape = "sphere", fail.status = CellStatus::fail, fail.metrics.bad_pixels = 12, fail.message = "12 interior pixels over 0.001";
  known = fail, known.shape = "torus", known.known_failure = true, known.known_reason = "issue 12";
  error.shape = "plane", error.status = CellStatus::error, error.metrics = {}, error.message = "compile: error";
  skipped.shape = "quad", skipped.status = CellStatus::skipped, skipped.metrics = {};
  part.results = {part.results[0], fail, known, error, skipped};
  std::vector<std::string> rejudged;
  auto merged = merge_shards({part}, {"a.json"}, &rejudged);
  ASSERT_TRUE(merged);
  EXPECT_TRUE(rejudged.empty()) << rejudged.front();
  std::map<std::string, const CellResult*> by_shape;
  for (const CellResult& r : merged->results) by_shape[r.shape] = &r;
  EXPECT_EQ(by_shape["sphere"]->message, "12 interior pixels over 0.001");
  EXPECT_TRUE(by_shape["torus"]->known_failure);
  EXPECT_EQ(by_shape["plane"]->status, CellStatus::error);
  EXPECT_EQ(by_shape["quad"]->status, CellStatus::skipped);
}

TEST(ShardMerge, AKnownFailureOrASkipThatItsMetricsDenyIsAFailure) {
  RunReport part = shard("abc", "", "cube");
  CellResult known = part.results[0], bare = part.results[0], skipped = part.results[0];
  known.shape = "sphere", known.status = CellStatus::fail, known.known_failure = true, known.known_reason = "issue 12";
  bare.shape = "torus", bare.status = CellStatus::fail, bare.metrics.bad_pixels = 4, bare.known_failure = true;
  skipped.shape = "quad", skipped.status = CellStatus::skipped, skipped.metrics.bad_pixels = 90;
  part.results = {known, bare, skipped};
  std::vector<std::string> rejudged;
  auto merged = merge_shards({part}, {"a.json"}, &rejudged);
  ASSERT_TRUE(merged);
  EXPECT_EQ(rejudged.size(), 3u);
  for (const CellResult& r : merged->results) {
    EXPECT_EQ(r.status, CellStatus::fail) << r.id();
    EXPECT_FALSE(r.known_failure) << r.id();
    EXPECT_EQ(r.message.rfind("shard said ", 0), 0u) << r.message;
  }
  EXPECT_FALSE(merged->acceptable());
}

}  // namespace
}  // namespace shaderbed
