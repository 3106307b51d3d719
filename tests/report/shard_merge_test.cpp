// merge: the shards of one run join into one report; shards of different runs are
// refused, and a missing or interrupted shard leaves the merged report incomplete.
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
  auto cell = merge_shards({shard("", "", "cube"), shard("", "", "cube")}, {"a.json", "b.json"});
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

}  // namespace
}  // namespace shaderbed
