// The bench's accounting on a hand-built report: times the runner copies into several
// cells (a program's compile, a group's reference) are counted once; a cached pipeline's
// build is not counted; the parts, the shares and the unaccounted rest add up.
#include <gtest/gtest.h>

#include "bench/SuiteCost.h"

namespace shaderbed::bench {
namespace {

CellResult cell(std::string case_name, std::string variant, std::string language, std::string backend,
                std::string shape, double compile, double reference, double build, bool cached) {
  CellResult r{.case_name = std::move(case_name), .variant = std::move(variant), .language = std::move(language),
               .backend = std::move(backend), .path = "spirv", .shape = std::move(shape), .status = CellStatus::pass};
  r.time_ms = {{"compile", compile}, {"reference", reference}, {"build", build},
               {"draw", 2},          {"readback", 0.5},        {"compare", 0.25}};
  r.program_cached = cached;
  return r;
}

// Two programs (phong/pixel in glsl and hlsl), two groups (sphere, torus), two backends.
RunReport with_workers(RunReport report, int workers) {
  report.workers = workers;
  return report;
}

RunReport two_programs_two_groups() {
  RunReport report;
  report.wall_ms = 100;
  for (const char* shape : {"sphere", "torus"}) {
    const bool second_shape = std::string(shape) == "torus";
    const double reference = second_shape ? 30 : 20;
    for (const char* language : {"glsl", "hlsl"}) {
      const double compile = std::string(language) == "glsl" ? 5 : 7;
      for (const char* backend : {"vulkan", "gl"})
        report.results.push_back(cell("phong", "pixel", language, backend, shape, compile, reference,
                                      second_shape ? 0 : 3, second_shape));
    }
  }
  return report;
}

double part(const SuiteCost& cost, const std::string& name) {
  for (const CostPart& p : cost.parts)
    if (p.name == name) return p.ms;
  ADD_FAILURE() << "no part " << name;
  return 0;
}

size_t count(const SuiteCost& cost, const std::string& name) {
  for (const CostPart& p : cost.parts)
    if (p.name == name) return p.count;
  return 0;
}

TEST(SuiteCost, CompileCountedOncePerProgram) {
  const SuiteCost cost = suite_cost(with_workers(two_programs_two_groups(), 1));
  EXPECT_DOUBLE_EQ(part(cost, "compile"), 5 + 7);
  EXPECT_EQ(count(cost, "compile"), 2u);
}

TEST(SuiteCost, ReferenceCountedOncePerGroup) {
  const SuiteCost cost = suite_cost(with_workers(two_programs_two_groups(), 1));
  EXPECT_DOUBLE_EQ(part(cost, "reference"), 20 + 30);
  EXPECT_EQ(count(cost, "reference"), 2u);
}

TEST(SuiteCost, ShPrecomputeCountedOncePerCaseAndShape) {
  RunReport report = two_programs_two_groups();
  for (CellResult& r : report.results) {
    r.sh = CellResult::ShErrors{};
    r.sh->precompute_ms = r.shape == "sphere" ? 40 : 60;   // every cell of a shape copies its shape's
  }
  const SuiteCost cost = suite_cost(with_workers(report, 1));
  EXPECT_DOUBLE_EQ(part(cost, "precompute"), 40 + 60);
  EXPECT_EQ(count(cost, "precompute"), 2u);
  EXPECT_DOUBLE_EQ(part(suite_cost(with_workers(two_programs_two_groups(), 1)), "precompute"), 0) << "no SH case";
}

TEST(SuiteCost, CachedPipelinesAreNotBuilds) {
  const SuiteCost cost = suite_cost(with_workers(two_programs_two_groups(), 1));
  EXPECT_DOUBLE_EQ(part(cost, "build"), 4 * 3);
  EXPECT_EQ(count(cost, "build"), 4u);
}

TEST(SuiteCost, PerCellPartsCountEveryCell) {
  const SuiteCost cost = suite_cost(with_workers(two_programs_two_groups(), 1));
  EXPECT_EQ(cost.cells, 8u);
  EXPECT_DOUBLE_EQ(part(cost, "draw"), 8 * 2);
  EXPECT_DOUBLE_EQ(part(cost, "readback"), 8 * 0.5);
  EXPECT_DOUBLE_EQ(part(cost, "compare"), 8 * 0.25);
}

TEST(SuiteCost, DriverAndShaderbedSharesAddUp) {
  const SuiteCost cost = suite_cost(with_workers(two_programs_two_groups(), 1));
  EXPECT_DOUBLE_EQ(cost.driver_ms, 12 + 16 + 4);
  EXPECT_DOUBLE_EQ(cost.shaderbed_ms, 12 + 50 + 2);
  EXPECT_DOUBLE_EQ(cost.summed_ms, cost.driver_ms + cost.shaderbed_ms);
  EXPECT_DOUBLE_EQ(cost.driver_share() + cost.shaderbed_share(), 1);
}

TEST(SuiteCost, ImageIoIsShaderbedsOwnPerCellWhenImagesWereWritten) {
  EXPECT_EQ(count(suite_cost(with_workers(two_programs_two_groups(), 1)), "io"), 0u);   // no --out
  RunReport report = two_programs_two_groups();
  for (CellResult& r : report.results) r.time_ms["io"] = 1.5;
  const SuiteCost cost = suite_cost(with_workers(report, 1));
  EXPECT_EQ(count(cost, "io"), 8u);
  EXPECT_DOUBLE_EQ(part(cost, "io"), 8 * 1.5);
  EXPECT_DOUBLE_EQ(cost.shaderbed_ms, 12 + 50 + 2 + 12);
}

TEST(SuiteCost, UnaccountedIsWallTimesWorkersMinusParts) {
  const SuiteCost cost = suite_cost(with_workers(two_programs_two_groups(), 2));
  EXPECT_DOUBLE_EQ(cost.worker_ms, 200);
  EXPECT_DOUBLE_EQ(cost.unaccounted_ms, 200 - cost.summed_ms);
}

TEST(SuiteCost, CellThatCouldNotRunAddsOnlyWhatItMeasured) {
  RunReport report = two_programs_two_groups();
  CellResult broken{.case_name = "lambert", .variant = "pixel", .language = "glsl", .backend = "vulkan",
                    .path = "spirv", .shape = "cube", .status = CellStatus::error};
  broken.time_ms = {{"reference", 9}};   // the compile failed: no compile, build, draw, compare
  report.results.push_back(broken);
  const SuiteCost cost = suite_cost(with_workers(report, 1));
  EXPECT_EQ(cost.errors, 1u);
  EXPECT_DOUBLE_EQ(part(cost, "reference"), 20 + 30 + 9);
  EXPECT_DOUBLE_EQ(part(cost, "compile"), 12);
  EXPECT_EQ(count(cost, "draw"), 8u);
}

}  // namespace
}  // namespace shaderbed::bench
