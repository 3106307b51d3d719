// The hard-case metrics on values whose answers are known by construction.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "compare/NumericalError.h"

namespace shaderbed {
namespace {

TEST(UlpDistance, CountsRepresentableFloats) {
  EXPECT_EQ(ulp_distance(1.0f, 1.0f), 0u);
  EXPECT_EQ(ulp_distance(1.0f, std::nextafter(1.0f, 2.0f)), 1u);
  float f = 1.0f;
  for (int i = 0; i < 10; ++i) f = std::nextafter(f, 0.0f);
  EXPECT_EQ(ulp_distance(1.0f, f), 10u);
  EXPECT_EQ(ulp_distance(f, 1.0f), 10u);
  EXPECT_EQ(ulp_distance(0.0f, -0.0f), 0u);
  const float tiny = std::numeric_limits<float>::denorm_min();
  EXPECT_EQ(ulp_distance(-tiny, tiny), 2u);   // across zero: -tiny, 0, tiny
  EXPECT_EQ(ulp_distance(std::nanf(""), 1.0f), std::numeric_limits<uint64_t>::max());
}

TEST(RelativeError, UsesTheFloorNearZero) {
  EXPECT_NEAR(relative_error(1.001, 1.0), 1e-3, 1e-12);
  EXPECT_NEAR(relative_error(-2.0, -1.0), 1.0, 1e-12);
  EXPECT_NEAR(relative_error(1e-6, 0.0, 1e-3), 1e-3, 1e-12);
  EXPECT_NEAR(relative_error(1e-6, 0.0, 1e-6), 1.0, 1e-12);
  EXPECT_EQ(relative_error(std::nan(""), 1.0), std::numeric_limits<double>::infinity());
  EXPECT_EQ(relative_error(std::nan(""), std::nan("")), 0.0);
  EXPECT_EQ(relative_error(INFINITY, INFINITY), 0.0);
}

TEST(NumericalError, CountsNonFiniteAndMeasuresOnlyMeasuredPixels) {
  Image render(4, 1);
  std::vector<double> reference(16, 1.0);
  const float nan = std::nanf("");
  for (int c = 0; c < 3; ++c) {
    render.rgba[0 * 4 + c] = 1.5f;      // measured: relative error 0.5
    render.rgba[1 * 4 + c] = nan;       // NaN where the reference is 1: a mismatch
    render.rgba[2 * 4 + c] = 100.0f;    // finite_only: error not measured
    render.rgba[3 * 4 + c] = INFINITY;  // undefined: counted, never a mismatch
  }
  for (int c = 0; c < 3; ++c) reference[3 * 4 + c] = std::nan("");
  const std::vector<PixelJudgement> judgement = {PixelJudgement::measured, PixelJudgement::measured,
                                                 PixelJudgement::finite_only, PixelJudgement::undefined};
  const NumericalError e = numerical_error(render, reference, judgement);
  EXPECT_EQ(e.pixels, 4u);
  EXPECT_EQ(e.measured_pixels, 1u);
  EXPECT_EQ(e.render_nonfinite, 2u);
  EXPECT_EQ(e.render_nan, 1u);
  EXPECT_EQ(e.render_inf, 1u);
  EXPECT_EQ(e.reference_nonfinite, 1u);
  EXPECT_EQ(e.nonfinite_mismatch, 1u);
  EXPECT_NEAR(e.max_relative, 0.5, 1e-12);
  EXPECT_EQ(e.max_relative_pixel, 0);
  EXPECT_EQ(e.max_ulps, ulp_distance(1.5f, 1.0f));
}

}  // namespace
}  // namespace shaderbed
