// The shader's twin in a run (--twin, reference = { twin = ... }): a min16float port only the
// half twin catches, a NaN traced to the line that makes it, and a differential case judged
// by its original's double twin.
#include <gtest/gtest.h>

#include "RealWorldRuns.h"
#include "run/Runner.h"

namespace shaderbed {
namespace {

const std::string kTwinCases = std::string(SHADERBED_SOURCE_DIR) + "/tests/twin/cases";

RunReport run_twin_case(const std::string& name, const std::string& twin) {
  RunOptions o = test::quick_run(kTwinCases, name, 48);
  o.select.shapes = {"sphere"};
  o.cell.twin = twin;
  auto report = run_suite(o);
  EXPECT_TRUE(report) << report.error().to_string();
  return report ? std::move(*report) : RunReport{};
}

bool has_warning(const CellResult& r, const std::string& text) {
  for (const std::string& w : r.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

TEST(Twin, AMin16floatPortPassesOnDesktopDriversAndOnlyTheHalfTwinShowsIt) {
  for (const std::string twin : {"", "float", "half"}) {
    SCOPED_TRACE("--twin " + twin);
    const RunReport report = run_twin_case("min16_port", twin);
    ASSERT_EQ(report.results.size(), 6u);
    for (const CellResult& r : report.results) {
      EXPECT_EQ(r.status, CellStatus::pass) << r.id() << ": " << r.message;
      const bool noted = r.twin && !r.twin->precision_note.empty();
      if (twin != "half" || r.variant == "original") {
        EXPECT_FALSE(noted) << r.id() << ": " << r.twin->precision_note;
        continue;
      }
      ASSERT_TRUE(noted) << r.id();
      // 16-bit pow(x, 60) near the highlight: far over fp32's tolerance, named by its lines.
      EXPECT_GT(r.twin->share, 10) << r.id();
      EXPECT_NE(r.twin->precision_note.find("highlight_min16.hlsl:26"), std::string::npos) << r.twin->precision_note;
      EXPECT_TRUE(has_warning(r, "precision: a device that computes RelaxedPrecision")) << r.id();
    }
  }
}

TEST(Twin, TheNaNOfAPlantedSqrtIsTracedToItsLine) {
  const RunReport report = run_twin_case("nan_line", "double");
  ASSERT_FALSE(report.results.empty());
  for (const CellResult& r : report.results) {
    EXPECT_EQ(r.status, CellStatus::fail) << r.id();
    ASSERT_TRUE(r.twin) << r.id();
    EXPECT_NE(r.twin->nonfinite_origin.find("nan_line.frag:16 `float soft = sqrt(facing);`"), std::string::npos)
        << r.id() << ": " << r.twin->nonfinite_origin;
    EXPECT_NE(r.twin->nonfinite_origin.find("GLSL.std.450 Sqrt(facing = -"), std::string::npos) << r.twin->nonfinite_origin;
    // Beside the model, the exact shader fails as the render does: the formula is wrong.
    EXPECT_GT(r.twin->reference_max_abs, 0.1) << r.id();
    EXPECT_LT(r.twin->max_abs, 1e-5) << r.id();
    // With one language the renders alone cannot tell the front end from the model; the
    // twin says the SPIR-V itself computes it.
    EXPECT_EQ(r.attribution, "shader") << r.id() << ": " << r.attribution_reason;
  }
}

TEST(Twin, ADifferentialCaseNamingOnlyTheOriginalsLanguageIsJudgedByItsDoubleTwin) {
  const RunReport report = run_twin_case("min16_port", "");
  ASSERT_EQ(report.results.size(), 6u);
  for (const CellResult& r : report.results) {
    EXPECT_NE(r.reference.label.find("twin-double"), std::string::npos) << r.id() << ": " << r.reference.label;
    // Against an exact baseline a correct fp32 render is a few ulp of its values (up to ~1.5) away.
    EXPECT_LT(r.metrics.max_abs, 5e-5) << r.id();
  }
}

}  // namespace
}  // namespace shaderbed
