#include <gtest/gtest.h>

#include "sweep/SweepAxis.h"

namespace shaderbed {
namespace {

TEST(SweepAxis, LutSizesOverDecadesAreGeometricIntegers) {
  auto axis = parse_sweep_axis("lut_size=8:256:6");
  ASSERT_TRUE(axis) << axis.error().to_string();
  EXPECT_EQ(axis->name, "lut_size");
  EXPECT_TRUE(axis->integer);
  EXPECT_EQ(axis->values, (std::vector<double>{8, 16, 32, 64, 128, 256}));
}

TEST(SweepAxis, NarrowRangesAreLinearAndSpacingCanBeChosen) {
  EXPECT_EQ(parse_sweep_axis("power=10:40:4")->values, (std::vector<double>{10, 20, 30, 40}));
  EXPECT_EQ(parse_sweep_axis("power=1:100:3:lin")->values, (std::vector<double>{1, 50.5, 100}));
  EXPECT_EQ(parse_sweep_axis("slope_m=0.001:0.1:3:log")->values.size(), 3u);
  EXPECT_NEAR(parse_sweep_axis("slope_m=0.001:0.1:3:log")->values[1], 0.01, 1e-15);
  EXPECT_EQ(parse_sweep_axis("slope_m=0.5:0.5:1")->values, (std::vector<double>{0.5}));
}

TEST(SweepAxis, RoundedDuplicatesAreDropped) {
  EXPECT_EQ(parse_sweep_axis("tessellation=4:6:5")->values, (std::vector<double>{4, 5, 6}));
}

TEST(SweepAxis, BadTextIsAnErrorNamingTheAxis) {
  for (const char* bad : {"lut_size", "lut_size=8:256", "lut_size=8:x:6", "lut_size=8:256:0", "lut_size=8:256:2.5",
                          "lut_size=8:256:6:cubic", "power=-1:10:3:log", "=1:2:3"}) {
    auto axis = parse_sweep_axis(bad);
    ASSERT_FALSE(axis) << bad;
    EXPECT_EQ(axis.error().stage, ErrorStage::options) << bad;
  }
  EXPECT_NE(parse_sweep_axis("power=1:x:3").error().message.find("'x' is not a number"), std::string::npos);
}

}  // namespace
}  // namespace shaderbed
