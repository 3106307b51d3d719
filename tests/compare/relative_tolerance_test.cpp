// A tolerance with a relative part: a channel passes when |render - reference| <=
// max_abs + max_rel |reference|, so bright pixels may differ more than dark ones, and the
// share of the tolerance used is reported.
#include <gtest/gtest.h>

#include "CompareTestSupport.h"
#include "compare/ImageComparison.h"

namespace shaderbed {
namespace {

using namespace compare_test;

TEST(RelativeTolerance, ScalesWithThePixelsMagnitude) {
  const ReferenceImage ref = disc_reference();
  // Every channel 1e-4 relative too bright: within 1e-6 + 2e-4 |ref|, not within 1e-6 alone.
  const Image render = disc_render(20, 32, 32, kSize, [](double v, int) { return v * (1 + 1e-4); });
  const Comparison relative = compare_images(render, ref, {1e-6, 1e-2, 2e-4, 0});
  EXPECT_TRUE(relative.pass) << relative.reason;
  EXPECT_GT(relative.interior_tolerance_share, 0.3);
  EXPECT_LT(relative.interior_tolerance_share, 0.6);
  const Comparison absolute = compare_images(render, ref, {1e-6, 1e-2});
  EXPECT_FALSE(absolute.pass);
  EXPECT_GT(absolute.interior_tolerance_share, 1.0);
}

TEST(RelativeTolerance, TheFailureMessageStatesTheFormula) {
  const ReferenceImage ref = disc_reference();
  const Image render = disc_render(20, 32, 32, kSize, [](double v, int) { return v * 1.01; });
  const Comparison c = compare_images(render, ref, {1e-5, 1e-2, 1e-4, 1e-3});
  EXPECT_FALSE(c.pass);
  EXPECT_NE(c.reason.find("interior pixels over 1e-05 + 0.0001|ref|"), std::string::npos) << c.reason;
}

TEST(RelativeTolerance, ZeroToleranceOnlyPassesExactMatches) {
  const Image render = disc_render();
  const ReferenceImage ref{render.width, render.height, std::vector<double>(render.rgba.begin(), render.rgba.end()),
                           render.coverage};
  EXPECT_TRUE(compare_images(render, ref, {0, 0}).pass);
  const Image off = disc_render(20, 32, 32, kSize, [](double v, int) { return v + 1e-6; });
  EXPECT_FALSE(compare_images(off, ref, {0, 0}).pass);
}

}  // namespace
}  // namespace shaderbed
