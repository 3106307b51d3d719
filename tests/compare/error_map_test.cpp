// The error PNG's false colours (compare/ErrorMap.h): a scale from 0 to the worst interior
// error, which lands on the top colour at the recorded pixel, the threshold always on the
// scale, NaN/Inf in a colour the ramp never reaches, background as in the renders.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "CompareTestSupport.h"
#include "TestThresholds.h"
#include "compare/ErrorMap.h"
#include "compare/ImageComparison.h"
#include "report/ErrorScale.h"

namespace shaderbed {
namespace {

using namespace compare_test;

Rgb8 map_pixel(const ErrorMap& map, int x, int y) {
  const uint8_t* p = &map.rgb[(size_t(y) * map.width + x) * 3];
  return {p[0], p[1], p[2]};
}

TEST(ErrorMap, WorstInteriorErrorIsTheTopOfTheScaleAtItsPixel) {
  const ReferenceImage ref = disc_reference();
  Image render = copy_of(ref);
  // Two wrong interior pixels: 0.3 (the worst) and 0.15 (half way up the scale).
  render.pixel(30, 31)[1] += 0.3f;
  render.pixel(34, 33)[0] += 0.15f;
  const Comparison cmp = compare_images(render, ref, test::kThresholds);
  const ErrorMap map = error_map(cmp.error, 1e-3);
  EXPECT_EQ(map.scale.peak_x, 30);
  EXPECT_EQ(map.scale.peak_y, 31);
  EXPECT_NEAR(map.scale.peak, 0.3, 1e-6);
  EXPECT_EQ(map.scale.top, map.scale.peak) << "the worst error, not the threshold, when it is larger";
  EXPECT_EQ(map_pixel(map, 30, 31), kErrorScaleStops.back());
  EXPECT_EQ(map_pixel(map, 34, 33), error_scale_colour(0.15 / map.scale.top));
  EXPECT_EQ(map_pixel(map, 32, 32), kErrorScaleStops.front()) << "no error: the bottom of the scale";
  EXPECT_EQ(map_pixel(map, 0, 0), (Rgb8{26, 28, 36})) << "background as write_png draws it";
}

TEST(ErrorMap, ThresholdTopsTheScaleOfAPassingImage) {
  const ReferenceImage ref = disc_reference();
  Image render = copy_of(ref);
  render.pixel(32, 32)[2] += 5e-4f;
  const ErrorMap map = error_map(compare_images(render, ref, test::kThresholds).error, 1e-3);
  EXPECT_EQ(map.scale.top, 1e-3);
  EXPECT_EQ(map_pixel(map, 32, 32), error_scale_colour(map.scale.peak / 1e-3));
  EXPECT_NE(map_pixel(map, 32, 32), kErrorScaleStops.back());
}

TEST(ErrorMap, NonFiniteMismatchIsItsOwnColourAndNotTheTop) {
  const ReferenceImage ref = disc_reference();
  Image render = copy_of(ref);
  render.pixel(32, 32)[0] = std::numeric_limits<float>::quiet_NaN();
  render.pixel(28, 30)[0] += 0.01f;
  const ErrorMap map = error_map(compare_images(render, ref, test::kThresholds).error, 1e-3);
  EXPECT_EQ(map_pixel(map, 32, 32), kErrorNonFinite);
  EXPECT_NEAR(map.scale.top, 0.01, 1e-6) << "the scale is the finite errors'";
  for (int t = 0; t <= 100; ++t) EXPECT_NE(error_scale_colour(t / 100.0), kErrorNonFinite);
}

TEST(ErrorScale, RampEndsAtItsStopsAndTheGradientNamesThem) {
  EXPECT_EQ(error_scale_colour(0), kErrorScaleStops.front());
  EXPECT_EQ(error_scale_colour(1), kErrorScaleStops.back());
  EXPECT_EQ(error_scale_colour(7), kErrorScaleStops.back()) << "above the top: clamped";
  EXPECT_EQ(error_scale_colour(0.5), kErrorScaleStops[2]);
  EXPECT_EQ(error_scale_gradient(),
            "linear-gradient(to right, #0d0887 0%, #7e03a8 25%, #cc4778 50%, #f89540 75%, #f0f921 100%)");
}

}  // namespace
}  // namespace shaderbed
