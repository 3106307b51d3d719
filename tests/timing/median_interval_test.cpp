#include <gtest/gtest.h>

#include "timing/MedianInterval.h"

namespace shaderbed {
namespace {

TEST(MedianInterval, MedianOfOddAndEvenCounts) {
  EXPECT_EQ(median_interval({3, 1, 2}).median, 2);
  EXPECT_EQ(median_interval({4, 1, 3, 2}).median, 2.5);
  EXPECT_EQ(median_interval({}).samples, 0);
}

TEST(MedianInterval, FewSamplesGiveMinToMaxWithTheirTrueCoverage) {
  const MedianInterval m = median_interval({5, 1, 4, 2, 3});
  EXPECT_EQ(m.low, 1);
  EXPECT_EQ(m.high, 5);
  EXPECT_DOUBLE_EQ(m.level, 1 - 2.0 / 32);   // 1 - 2 P(B <= 0), B ~ Bin(5, 1/2)
}

TEST(MedianInterval, RanksReachNinetyFivePercentWithMoreSamples) {
  std::vector<double> samples;
  for (int i = 1; i <= 20; ++i) samples.push_back(i);
  const MedianInterval m = median_interval(samples);
  // Bin(20, 1/2): P(B <= 5) = 0.0207, P(B <= 6) = 0.0577, so ranks 6 and 15.
  EXPECT_EQ(m.low, 6);
  EXPECT_EQ(m.high, 15);
  EXPECT_NEAR(m.level, 1 - 2 * 0.020695, 1e-5);
  EXPECT_GE(m.level, 0.95);
}

TEST(MedianInterval, AnOutlierMovesNeitherTheMedianNorTheInterval) {
  const MedianInterval calm = median_interval({1.0, 1.1, 0.9, 1.05, 0.95, 1.02, 0.98, 1.01, 0.99});
  const MedianInterval spiked = median_interval({1.0, 99.0, 0.9, 1.05, 0.95, 1.02, 0.98, 1.01, 0.99});
  EXPECT_EQ(calm.median, spiked.median);
  EXPECT_EQ(calm.low, spiked.low);
  EXPECT_EQ(calm.high, spiked.high);
}

}  // namespace
}  // namespace shaderbed
