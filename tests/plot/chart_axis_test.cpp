// Axis decisions: when to go log, and where values a log axis cannot show are drawn.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "NonFinite.h"
#include "plot/ChartAxis.h"

namespace shaderbed {
namespace {

using test::kNaN;
using test::kInf;

TEST(ChartAxis, AutomaticGoesLogOnlyPastTwoDecades) {
  EXPECT_TRUE(plan_axis(std::vector{0.01, 0.5, 3.0}, AxisScale::automatic, "x").log);   // 2.5 decades
  EXPECT_FALSE(plan_axis(std::vector{0.05, 0.5, 3.0}, AxisScale::automatic, "x").log);  // 1.8 decades
  EXPECT_FALSE(plan_axis(std::vector{1.0, 100.0}, AxisScale::automatic, "x").log);      // exactly 2: not more
  EXPECT_FALSE(plan_axis(std::vector{-1000.0, 1.0, 2.0}, AxisScale::automatic, "x").log);  // positives span < 2
}

TEST(ChartAxis, RangeHoldsEveryValueWithAMargin) {
  const ChartAxis a = plan_axis(std::vector{2.0, 4.0, 3.0}, AxisScale::linear, "x");
  EXPECT_LT(a.low, 2.0);
  EXPECT_GT(a.high, 4.0);
  const ChartAxis l = plan_axis(std::vector{1e-4, 1.0, 10.0}, AxisScale::automatic, "x");
  ASSERT_TRUE(l.log);
  EXPECT_GT(l.low, 0.0);
  EXPECT_LT(l.low, 1e-4);
  EXPECT_GT(l.high, 10.0);
  const ChartAxis one = plan_axis(std::vector{5.0}, AxisScale::automatic, "x");
  EXPECT_LT(one.low, 5.0);
  EXPECT_GT(one.high, 5.0);
}

TEST(ChartAxis, NonPositiveValuesOnALogAxisAreDrawnAtAFloorAndSaidSo) {
  const ChartAxis a = plan_axis(std::vector{0.0, 1e-3, 1.0, -2.0}, AxisScale::log, "error");
  ASSERT_TRUE(a.log);
  EXPECT_EQ(a.clamped, 2);
  EXPECT_DOUBLE_EQ(a.floor, 1e-4);
  EXPECT_DOUBLE_EQ(a.position(0.0), 1e-4);
  EXPECT_DOUBLE_EQ(a.position(-2.0), 1e-4);
  EXPECT_DOUBLE_EQ(a.position(1e-3), 1e-3);
  EXPECT_LT(a.low, a.floor);
  EXPECT_NE(a.note.find("2 points with error <= 0 drawn at 0.0001"), std::string::npos) << a.note;
}

TEST(ChartAxis, LogRequestedWithoutPositiveValuesFallsBackToLinearAndSaysSo) {
  const ChartAxis a = plan_axis(std::vector{0.0, -1.0}, AxisScale::log, "error");
  EXPECT_FALSE(a.log);
  EXPECT_NE(a.note.find("linear"), std::string::npos) << a.note;
}

TEST(ChartAxis, NonFiniteValuesGetTheirOwnStripInsideTheRange) {
  const ChartAxis a = plan_axis(std::vector{1.0, 2.0, kNaN, -kInf}, AxisScale::linear, "x");
  EXPECT_GT(a.position(kNaN), 2.0);
  EXPECT_EQ(a.position(kInf), a.position(kNaN));
  EXPECT_LT(a.position(kNaN), a.high);
  EXPECT_LT(a.position(-kInf), 1.0);
  EXPECT_GT(a.position(-kInf), a.low);
  EXPECT_TRUE(a.note.empty());
}

TEST(ChartAxis, OnlyNonFiniteValuesStillGiveARange) {
  const ChartAxis a = plan_axis(std::vector{kNaN, kInf}, AxisScale::automatic, "x");
  EXPECT_TRUE(std::isfinite(a.low) && std::isfinite(a.high));
  EXPECT_LT(a.low, a.position(kNaN));
  EXPECT_LT(a.position(kNaN), a.high);
}

}  // namespace
}  // namespace shaderbed
