// Real runs of the hard-case suite on both backends (lavapipe and OSMesa): the robust
// variants stay finite where the book's do not, a deliberately broken shader is caught,
// and a stable form beats the book's on a sharp lobe. Relations only: every number is
// computed by the run.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "hard/HardRunner.h"

namespace shaderbed::hard {
namespace {

const std::filesystem::path kSource = SHADERBED_SOURCE_DIR;

std::vector<const HardRow*> rows(const HardReport& r, const std::string& kind) {
  std::vector<const HardRow*> out;
  for (const HardRow& row : r.rows)
    if (row.kind == kind) out.push_back(&row);
  return out;
}

void expect_both_backends(const std::vector<const HardRow*>& rs) {
  for (const char* backend : {"vulkan", "gl"})
    EXPECT_TRUE(std::any_of(rs.begin(), rs.end(), [&](const HardRow* r) { return r->backend == backend; })) << backend;
  for (const HardRow* r : rs) EXPECT_NE(r->status, CellStatus::error) << r->message;
}

TEST(HardRun, BrokenShaderIsCaughtAndRobustOneIsClean) {
  HardOptions o{.languages = {"glsl"}, .scenarios = {"sphere_perpendicular"}, .size = 33,
                .cases_dir = (kSource / "tests" / "hard" / "cases").string()};
  o.cases = {"ward_iso_ungated"};
  auto report = run_hard_cases(o);
  ASSERT_TRUE(report) << report.error().to_string();
  const auto book = rows(*report, "book"), robust = rows(*report, "robust");
  ASSERT_FALSE(book.empty());
  ASSERT_FALSE(robust.empty());
  expect_both_backends(book);
  expect_both_backends(robust);
  for (const HardRow* r : book) {
    // The ungated 1/sqrt((N.L)(N.V)) is NaN on the unlit and back-facing pixels.
    EXPECT_GT(r->error.nonfinite_mismatch, 0u) << r->backend;
    EXPECT_EQ(r->status, CellStatus::fail) << r->backend;
  }
  for (const HardRow* r : robust) {
    EXPECT_EQ(r->error.render_nonfinite, 0u) << r->backend;
    EXPECT_EQ(r->status, CellStatus::pass) << r->backend << ": " << r->message;
  }
  ASSERT_EQ(report->summaries.size(), 1u);
  EXPECT_GT(report->summaries[0].book_nonfinite, report->summaries[0].robust_nonfinite);
}

TEST(HardRun, PointLightOnTheSurfaceHasOneUndefinedPixelAndRobustStaysFinite) {
  HardOptions o{.cases = {"point_attenuated"}, .languages = {"glsl"}, .scenarios = {"light_on_surface"}, .size = 33};
  auto report = run_hard_cases(o);
  ASSERT_TRUE(report) << report.error().to_string();
  const auto book = rows(*report, "book"), robust = rows(*report, "robust");
  expect_both_backends(robust);
  for (const HardRow* r : robust) {
    EXPECT_EQ(r->error.render_nonfinite, 0u) << r->backend;
    EXPECT_EQ(r->status, CellStatus::pass) << r->backend << ": " << r->message;
  }
  for (const HardRow* r : book)
    if (r->variant == "pixel") {
      EXPECT_EQ(r->error.reference_nonfinite, 1u) << "d = 0 at exactly the centre pixel";
    }
}

TEST(HardRun, StableFormBeatsTheBookOnTheSharpestCookTorranceLobe) {
  HardOptions o{.cases = {"cook_torrance"}, .languages = {"glsl"}, .scenarios = {"lobe_sharp"}, .size = 33};
  auto report = run_hard_cases(o);
  ASSERT_TRUE(report) << report.error().to_string();
  const auto book = rows(*report, "book"), robust = rows(*report, "robust");
  expect_both_backends(robust);
  double book_worst = 0;
  for (const HardRow* r : book) book_worst = std::max(book_worst, r->error.max_relative);
  for (const HardRow* r : robust) {
    EXPECT_GT(r->error.measured_pixels, 0u);
    EXPECT_EQ(r->status, CellStatus::pass) << r->backend << ": " << r->message;
    EXPECT_LT(r->error.max_relative, book_worst) << r->backend;
  }
}

TEST(HardRun, UnknownNamesAreErrors) {
  EXPECT_FALSE(run_hard_cases({.cases = {"no_such_case"}}));
  EXPECT_FALSE(run_hard_cases({.cases = {"lambert"}, .scenarios = {"no_such_scenario"}}));
  EXPECT_FALSE(run_hard_cases({.cases = {"lambert"}, .size = 2}));
}

TEST(HardRun, LobeMapFindsTheBookFormulaLosingThePeakOfSharpLobes) {
  HardOptions o{.cases = {"cook_torrance"}, .backends = {"vulkan"}, .languages = {"glsl"}, .scenarios = {"lobe_map"},
                .size = 33};
  auto report = run_hard_cases(o);
  ASSERT_TRUE(report) << report.error().to_string();
  const HardRow* book = nullptr;
  const HardRow* robust = nullptr;
  for (const HardRow& r : report->rows) {
    if (r.variant == "pixel") book = &r;
    if (r.variant == "pixel_robust") robust = &r;
  }
  ASSERT_TRUE(book && robust);
  ASSERT_EQ(book->status == CellStatus::error || robust->status == CellStatus::error, false) << book->message << robust->message;
  // The same map, drawn a row at a time with each row's slope: the book's N.H form is far
  // off near the peak of the sharp rows, the cross-product form is not.
  EXPECT_EQ(book->status, CellStatus::fail);
  EXPECT_EQ(robust->status, CellStatus::pass) << robust->message;
  EXPECT_GT(book->error.max_relative, 100 * robust->error.max_relative);
}

}  // namespace
}  // namespace shaderbed::hard
