// The options an isolated worker receives: one encoder and one decoder, which agree on
// every field, send nothing the supervisor alone reads, and change no process state.
#include <gtest/gtest.h>

#include "backends/Backend.h"
#include "core/CacheSettings.h"
#include "run/WorkerOptions.h"

namespace shaderbed {
namespace {

// Every field away from its default, so a field the codec drops comes back different.
WorkerOptions unusual_options() {
  WorkerOptions o;
  o.select = {.cases_dir = "/cases", .cases = {"phong", "ward"}, .variants = {"pixel"}, .backends = {"gl"},
              .languages = {"hlsl", "cg"}, .shapes = {"torus"}, .params = {"power=30", "diffuse=0.5,0.25,1"},
              .shard = "2/3"};
  o.cell = {.size = 48,
            .out_dir = "/out",
            .save_images_dir = "/good",
            .against_dir = "/known",
            .timing = {.warmup = 3, .runs = 9},
            .mesh_slices = 17,
            .relaxed_precision = true,
            .per_pixel_reference = true,
            .unused_binding_warnings = false,
            .twin = "half",
            .keep_images = "all"};
  o.process = {.caches = {.root = "/cache", .driver = false, .compile = false},
               .vulkan_device = "1",
               .gl_platform = {.platform = "egl", .device = "renderD129"}};
  return o;
}

TEST(WorkerOptions, RoundTripsEveryField) {
  const WorkerOptions sent = unusual_options();
  const auto received = decode_worker_options(encode_worker_options(sent));
  ASSERT_TRUE(received) << received.error().to_string();
  EXPECT_EQ(*received, sent);
  EXPECT_EQ(encode_worker_options(*received), encode_worker_options(sent));
}

// A path is bytes: a Latin-1 folder name (not UTF-8) and a UTF-8 one both arrive unchanged.
TEST(WorkerOptions, PathsArriveByteForByte) {
  WorkerOptions sent = unusual_options();
  sent.select.cases_dir = "/cases/caf\xe9";
  sent.cell.out_dir = "/out/\xff\xfe/\xc3\xa9t\xc3\xa9";
  sent.cell.save_images_dir = "/nul\x01\x7f\x80";
  const auto received = decode_worker_options(encode_worker_options(sent));
  ASSERT_TRUE(received) << received.error().to_string();
  EXPECT_EQ(received->select.cases_dir, sent.select.cases_dir);
  EXPECT_EQ(received->cell.out_dir, sent.cell.out_dir);
  EXPECT_EQ(received->cell.save_images_dir, sent.cell.save_images_dir);
}

TEST(WorkerOptions, DefaultsRoundTrip) {
  const auto received = decode_worker_options(encode_worker_options({}));
  ASSERT_TRUE(received) << received.error().to_string();
  EXPECT_EQ(*received, WorkerOptions{});
}

TEST(WorkerOptions, DecodingChangesNoProcessState) {
  const CacheSettings before = cache_settings();
  const std::string device = chosen_vulkan_device();
  const GlPlatformChoice gl_platform = chosen_gl_platform();
  ASSERT_TRUE(decode_worker_options(encode_worker_options(unusual_options())));
  EXPECT_EQ(cache_settings().root, before.root);
  EXPECT_EQ(cache_settings().driver, before.driver);
  EXPECT_EQ(chosen_vulkan_device(), device);
  EXPECT_EQ(chosen_gl_platform(), gl_platform);
}

TEST(WorkerOptions, WorkersGetOnlyWhatCellsNeed) {
  RunOptions run;
  run.select.variants = {"pixel"};
  run.workers = {.jobs = 7, .worker_binary = "/bin/shaderbed", .compile_timeout_s = 1, .draw_timeout_s = 2,
                 .worker_memory_mb = 3};
  run.expectations = "/known-failures.toml";
  const std::string line = encode_worker_options(worker_options(run));
  for (const char* supervisor_only : {"worker_binary", "timeout", "memory", "jobs", "expectations", "known-failures"})
    EXPECT_EQ(line.find(supervisor_only), std::string::npos) << supervisor_only << " in " << line;
  // A --variant filter hides the other variants, so no binding can be called unused.
  EXPECT_FALSE(worker_options(run).cell.unused_binding_warnings);
  run.select.variants.clear();
  EXPECT_TRUE(worker_options(run).cell.unused_binding_warnings);
}

TEST(WorkerOptions, BadLinesAreErrors) {
  for (const char* line : {"", "not json", "[]", "{}", R"({"select": {}, "cell": {}, "process": {}})"}) {
    const auto decoded = decode_worker_options(line);
    ASSERT_FALSE(decoded) << line;
    EXPECT_EQ(decoded.error().stage, ErrorStage::worker) << line;
  }
}

}  // namespace
}  // namespace shaderbed
