#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "ReportTestSupport.h"
#include "report/JsonReport.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

// Every field of the model set to a distinct, non-default value.
RunReport every_field() {
  RunReport report;
  report.tools = {"glslang 12", "SPIRV-Tools 2022.4", "spirv-cross 2022.12", "Mesa 22.3.6 lavapipe", "Mesa 22.3.6 llvmpipe",
                  "15.0.6"};
  report.wall_ms = 9876.5;
  report.out_dir = "/tmp/out";
  report.shard = "2/4";
  CellResult r;
  r.case_name = "phong";
  r.variant = "pixel_lut";
  r.language = "hlsl";
  r.backend = "gl";
  r.path = "cross";
  r.shape = "torus";
  r.status = CellStatus::fail;
  r.message = "interior max error 0.5 > 0.001\nsecond line \"quoted\" \\ tab\t";
  r.attribution = "cross-compiler";
  r.attribution_reason = "only the SPIRV-Cross path differs";
  r.known_failure = true;
  r.known_reason = "SPIRV-Cross drops precise";
  CellMetrics& m = r.metrics;
  m.max_abs = 0.5;
  m.rmse = 0.0123456789012345;
  m.psnr = 38.1;
  m.bad_pixels = 17;
  m.nonfinite = 3;
  m.nonfinite_mismatch = 2;
  m.coverage_mismatch = 5;
  m.silhouette_max_abs = 0.75;
  m.interior_pixels = 1000;
  m.silhouette_pixels = 200;
  m.covered_pixels = 1195;
  m.reference_covered_pixels = 1200;
  m.expected_area = 1201.25;
  m.min_passing_interior = 0.5;
  m.min_passing_silhouette = 0.75;
  m.render_values = {1, 2, 3, 4, 5};
  m.reference_values = {6, 7, 8, 9, 10};
  r.interior_threshold = 1e-3;
  r.silhouette_threshold = 2e-2;
  r.lut_bound = 3.5e-4;
  r.lut_derivation = "256 entries, linear filtering: |f''| h^2 / 8";
  r.time_ms = {{"compile", 1.25}, {"build", 2.5}, {"draw", 0.125}, {"readback", 0.0625}, {"reference", 30}, {"compare", 4}};
  r.program_cached = true;
  r.gpu = {"GL_TIME_ELAPSED", 1, 5, {0.015, 0.014, 0.025, 0.9375}, {0.875, 0.8125, 1.5, 0.9375}};
  r.vertex_spirv_hash = "00112233aabbccdd";
  r.fragment_spirv_hash = "ffeeddccbbaa9988";
  r.artefacts = {"a.exr", "a.png", "a.error.exr", "a.error.png", "reference.png",
                 "v.spvasm", "f.spvasm", "v.cross.glsl", "f.cross.glsl", "stored/a.exr", {0.25, 0.25, 17, 3}};
  // A differential cell's fields: the tolerance's relative part and reason, the
  // reference it was judged against, the convention fits, the scene hash.
  m.tolerance_share = 4.5e3;
  r.interior_threshold_rel = 0x1p-13;
  r.silhouette_threshold_rel = 0x1p-10;
  r.tolerance_reason = "differential default";
  r.reference = {"images", "images in /tmp/good", false, "glslang 11 (stored) vs 12"};
  r.explanations = {{"constant_factor", "× π", 2e-6, 1e-6, 900, true, "matches the reference × π to 2e-6"},
                    {"gamma_encoded_render", "encoded", 0.25, 0.125, 900, false, "encoded fits only to 0.25"}};
  r.scene_hash = "52445d0d43dbdc6d";
  report.results.push_back(r);
  CellResult e;
  e.case_name = "lambert";
  e.variant = "vertex";
  e.language = "cg";
  e.backend = "vulkan";
  e.path = "spirv";
  e.shape = "cube";
  e.status = CellStatus::error;
  e.message = "x.cg:3:1: compile: syntax error";
  report.results.push_back(e);
  return report;
}

fs::path write_text(const std::string& name, const std::string& text) {
  const fs::path dir = test::fresh_dir("json");
  test::write_text(dir / name, text);
  return dir / name;
}

TEST(JsonReport, WritesSchemaVersionToolchainAndEveryCellField) {
  const std::string text = to_json(every_field());
  for (const char* needle :
       {"\"schema\": 2", "\"llvm\": \"15.0.6\"", "\"shard\": \"2/4\"", "\"verdict\": \"cross-compiler\"",
        "\"known\": true", "\"reason\": \"SPIRV-Cross drops precise\"", "\"nonfinite_mismatch\": 2",
        "\"min_passing\"", "\"expected_area\": 1201.25", "\"reference_covered_pixels\": 1200", "\"above_one\": 10",
        "\"vertex\": \"00112233aabbccdd\"", "\"fragment_cross_glsl\": \"f.cross.glsl\"", "\"bound\": 0.00035",
        "\"derivation\": \"256 entries", "\"readback\": 0.0625", "\"id\": \"phong/pixel_lut/hlsl/gl/cross/torus\"",
        "\"known\": 1", "\"error\": 1", "\"interior_rel\": 0.0001220703125", "\"toolchain_note\": \"glslang 11",
        "\"name\": \"constant_factor\"", "\"summary\": \"matches the reference × π to 2e-6\"", "\"fits\": false",
        "\"scene_hash\": \"52445d0d43dbdc6d\"", "\"stored_exr\": \"stored/a.exr\"", "\"tolerance_share\": 4500.0"})
    EXPECT_NE(text.find(needle), std::string::npos) << needle << "\n" << text;
  EXPECT_EQ(std::string(R"("schema")"), text.substr(text.find('"'), 8)) << "the version comes first";
}

// One spelling, "tools", as every JSON shaderbed writes; files from before say "tool".
TEST(JsonReport, WritesToolsAndStillReadsTool) {
  const std::string text = to_json(every_field());
  EXPECT_NE(text.find("\"tools\": {"), std::string::npos) << text;
  EXPECT_EQ(text.find("\"tool\":"), std::string::npos) << text;
  auto old = parse_json(R"({"schema": 2, "tool": {"glslang": "glslang 11", "mesa": {"gl": "llvmpipe"}}, "results": []})",
                        "old.json");
  ASSERT_TRUE(old) << old.error().to_string();
  EXPECT_EQ(old->tools.glslang, "glslang 11");
  EXPECT_EQ(old->tools.gl_driver, "llvmpipe");
}

// The default caches are under $HOME: the report writes them "~/...", naming no user's home.
TEST(JsonReport, CacheFoldersUnderHomeAreWrittenFromTilde) {
  const char* saved = std::getenv("HOME");
  const std::string before = saved ? saved : "";
  ::setenv("HOME", "/home/someone", 1);
  RunReport report;
  CacheUse& cache = report.cache.emplace();
  cache.driver_cache = cache.compile_cache = true;
  cache.driver_cache_dir = "/home/someone/.cache/shaderbed/mesa";
  cache.compile_cache_dir = "/srv/cache/compile";
  const std::string text = to_json(report);
  if (saved) ::setenv("HOME", before.c_str(), 1);
  else ::unsetenv("HOME");
  EXPECT_NE(text.find("\"dir\": \"~/.cache/shaderbed/mesa\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"dir\": \"/srv/cache/compile\""), std::string::npos) << "a folder elsewhere stays as given\n" << text;
  EXPECT_EQ(text.find("/home/someone"), std::string::npos) << text;
}

TEST(JsonReport, RoundTripIsExact) {
  const RunReport original = every_field();
  const fs::path file = test::fresh_dir("json_rt") / "sub" / "r.json";
  ASSERT_TRUE(write_json(original, file.string()));
  auto back = read_json(file.string());
  ASSERT_TRUE(back) << back.error().to_string();
  EXPECT_EQ(to_json(*back), to_json(original));

  // Spot checks on the model itself, not only its text.
  ASSERT_EQ(back->results.size(), 2u);
  const CellResult& r = back->results[0];
  EXPECT_EQ(back->tools.llvm, "15.0.6");
  EXPECT_EQ(back->tools.vulkan_driver, "Mesa 22.3.6 lavapipe");
  EXPECT_EQ(back->shard, "2/4");
  EXPECT_EQ(back->out_dir, "/tmp/out");
  EXPECT_EQ(back->wall_ms, 9876.5);
  EXPECT_EQ(r.id(), original.results[0].id());
  EXPECT_EQ(r.message, original.results[0].message);
  EXPECT_TRUE(r.known_failure);
  EXPECT_EQ(r.known_reason, "SPIRV-Cross drops precise");
  EXPECT_EQ(r.attribution_reason, "only the SPIRV-Cross path differs");
  EXPECT_EQ(r.metrics.rmse, 0.0123456789012345);
  EXPECT_EQ(r.metrics.reference_values.above_one, 10u);
  EXPECT_EQ(r.metrics.render_values.nan, 1u);
  EXPECT_EQ(r.metrics.min_passing_silhouette, 0.75);
  EXPECT_EQ(r.lut_bound, 3.5e-4);
  EXPECT_EQ(r.time_ms.at("readback"), 0.0625);
  EXPECT_EQ(r.artefacts.vertex_cross_glsl, "v.cross.glsl");
  EXPECT_EQ(r.artefacts.error_scale.top, 0.25);
  EXPECT_EQ(r.artefacts.error_scale.peak_x, 17);
  EXPECT_EQ(r.artefacts.error_scale.peak_y, 3);
  EXPECT_EQ(r.fragment_spirv_hash, "ffeeddccbbaa9988");
  EXPECT_TRUE(r.program_cached);
  EXPECT_EQ(r.gpu.clock, "GL_TIME_ELAPSED");
  EXPECT_EQ(r.gpu.runs, 5);
  EXPECT_EQ(r.gpu.wall.high, 1.5);
  EXPECT_EQ(r.gpu.device.level, 0.9375);
  EXPECT_EQ(r.reference.kind, "images");
  EXPECT_EQ(r.reference.toolchain_note, "glslang 11 (stored) vs 12");
  ASSERT_EQ(r.explanations.size(), 2u);
  EXPECT_EQ(r.explanations[0].residual, 2e-6);
  EXPECT_TRUE(r.explanations[0].fits);
  EXPECT_EQ(r.explanations[1].pixels, 900u);
  EXPECT_EQ(r.interior_threshold_rel, 0x1p-13);
  EXPECT_EQ(r.tolerance_reason, "differential default");
  EXPECT_EQ(r.metrics.tolerance_share, 4.5e3);
  EXPECT_EQ(back->results[1].status, CellStatus::error);
  EXPECT_FALSE(back->acceptable());
  fs::remove_all(file.parent_path().parent_path());
}

TEST(JsonReport, NonFiniteNumbersSurvive) {
  RunReport report = every_field();
  report.results[0].metrics.psnr = std::numeric_limits<double>::infinity();
  report.results[0].metrics.max_abs = std::numeric_limits<double>::quiet_NaN();
  report.results[0].metrics.silhouette_max_abs = -std::numeric_limits<double>::infinity();
  const std::string text = to_json(report);
  EXPECT_NE(text.find("\"psnr\": \"inf\""), std::string::npos);
  auto back = parse_json(text, "mem.json");
  ASSERT_TRUE(back) << back.error().to_string();
  EXPECT_TRUE(std::isinf(back->results[0].metrics.psnr) && back->results[0].metrics.psnr > 0);
  EXPECT_TRUE(std::isnan(back->results[0].metrics.max_abs));
  EXPECT_TRUE(std::isinf(back->results[0].metrics.silhouette_max_abs) && back->results[0].metrics.silhouette_max_abs < 0);
  EXPECT_EQ(to_json(*back), text);
  // null (what schema 1 wrote) reads as NaN.
  auto from_null = parse_json(R"({"schema": 2, "results": [{"case": "a", "variant": "b", "language": "glsl",
      "backend": "gl", "path": "native", "shape": "cube", "status": "pass", "metrics": {"psnr": null}}]})", "n.json");
  ASSERT_TRUE(from_null) << from_null.error().to_string();
  EXPECT_TRUE(std::isnan(from_null->results[0].metrics.psnr));
}

TEST(JsonReport, ReadsTheSampleRunAndAnEmptyOne) {
  const fs::path dir = test::fresh_dir("json_sample");
  const RunReport sample = test::sample_report(dir / "out", 8);
  auto back = parse_json(to_json(sample), "sample.json");
  ASSERT_TRUE(back) << back.error().to_string();
  EXPECT_EQ(to_json(*back), to_json(sample));
  auto empty = parse_json(to_json(RunReport{}), "empty.json");
  ASSERT_TRUE(empty) << empty.error().to_string();
  EXPECT_TRUE(empty->results.empty());
  fs::remove_all(dir);
}

TEST(JsonReport, SyntaxErrorsNameFileLineAndColumn) {
  const fs::path file = write_text("bad.json", "{\n  \"schema\": 2,\n  \"results\": [ }\n");
  auto r = read_json(file.string());
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().file, file.string());
  EXPECT_EQ(r.error().line, 3);
  EXPECT_GT(r.error().column, 0);
  EXPECT_NE(r.error().to_string().find(file.string() + ":3:"), std::string::npos) << r.error().to_string();
  EXPECT_NE(r.error().message.find("invalid JSON"), std::string::npos) << r.error().message;

  auto truncated = parse_json("{\"schema\": 2, \"results\": [", "t.json");
  ASSERT_FALSE(truncated);
  EXPECT_EQ(truncated.error().file, "t.json");
  fs::remove_all(file.parent_path());
}

TEST(JsonReport, RefusesOtherSchemaVersionsClearly) {
  for (const char* version : {"1", "3"}) {
    auto r = parse_json(std::string("{\"schema\": ") + version + ", \"results\": []}", "old.json");
    ASSERT_FALSE(r) << version;
    const std::string text = r.error().to_string();
    EXPECT_NE(text.find("old.json"), std::string::npos) << text;
    EXPECT_NE(text.find(std::string("schema version ") + version + " is not supported"), std::string::npos) << text;
    EXPECT_NE(text.find("reads version 2"), std::string::npos) << text;
  }
  auto none = parse_json(R"({"results": []})", "x.json");
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().message.find("not a shaderbed results file"), std::string::npos) << none.error().message;
  auto text = parse_json(R"({"schema": "2", "results": []})", "x.json");
  ASSERT_FALSE(text);
  EXPECT_NE(text.error().message.find("/schema"), std::string::npos);
}

TEST(JsonReport, WrongFieldsAreNamedByTheirPointer) {
  const std::string head = R"({"schema": 2, "results": [{"case": "a", "variant": "b", "language": "glsl",
      "backend": "gl", "path": "native", "shape": "cube", )";
  struct Bad {
    std::string body, pointer;
  } cases[] = {
      {R"("status": "maybe"})", "/results/0/status"},
      {R"("status": "pass", "metrics": {"bad_pixels": -1}})", "/results/0/metrics/bad_pixels"},
      {R"("status": "pass", "metrics": {"rmse": "lots"}})", "/results/0/metrics/rmse"},
      {R"("status": "pass", "metrics": {"values": {"render": {"nan": 1.5}}}})", "/results/0/metrics/values/render/nan"},
      {R"("status": "pass", "known_failure": {"known": "yes"}})", "/results/0/known_failure/known"},
      {R"("status": "pass", "time_ms": {"draw": "fast"}})", "/results/0/time_ms/draw"},
      {R"("status": "pass", "artefacts": []})", "/results/0/artefacts"},
  };
  for (const Bad& b : cases) {
    auto r = parse_json(head + b.body + "]}", "f.json");
    ASSERT_FALSE(r) << b.body;
    EXPECT_EQ(r.error().message.rfind(b.pointer + ":", 0), 0u) << r.error().message;
  }
  auto missing = parse_json(R"({"schema": 2, "results": [{"case": "a"}]})", "f.json");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("/results/0/variant: missing"), std::string::npos) << missing.error().message;
  auto not_array = parse_json(R"({"schema": 2, "results": {}})", "f.json");
  ASSERT_FALSE(not_array);
  EXPECT_NE(not_array.error().message.find("/results"), std::string::npos);
}

TEST(JsonReport, MissingFileIsAnError) {
  auto r = read_json("/nonexistent/shaderbed/r.json");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().file, "/nonexistent/shaderbed/r.json");
}

}  // namespace
}  // namespace shaderbed
