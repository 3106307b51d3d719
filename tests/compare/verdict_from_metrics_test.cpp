// A cell's verdict follows from the metrics a report keeps (report/CellVerdict.h), so
// `merge` can judge a cell read from a shard again: over many random renders, thresholds
// and defects, failed_checks on a comparison's metrics agrees with compare_images' own
// verdict, and a metric edited to fail is caught.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "CompareTestSupport.h"
#include "compare/ImageComparison.h"
#include "report/CellVerdict.h"

namespace shaderbed {
namespace {

using namespace compare_test;

TEST(VerdictFromMetrics, AgreesWithTheComparisonOverRandomRenders) {
  std::mt19937 rng(30);
  std::uniform_real_distribution<double> unit(0, 1);
  const ReferenceImage ref = disc_reference();
  int passes = 0, fails = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Image render = copy_of(ref);
    // Noise of a random size everywhere, a few pixels far off, sometimes NaN or a coverage flip.
    const double noise = std::pow(10.0, -7 + 6 * unit(rng));
    for (float& v : render.rgba) v += float(noise * (unit(rng) - 0.5));
    const int defects = int(rng() % 4);
    for (int d = 0; d < defects; ++d) {
      const int x = int(rng() % kSize), y = int(rng() % kSize);
      const size_t i = size_t(y) * kSize + x;
      switch (rng() % 4) {
        case 0: render.rgba[i * 4 + rng() % 3] += float(unit(rng)); break;
        case 1: render.rgba[i * 4] = std::numeric_limits<float>::quiet_NaN(); break;
        case 2: render.coverage[i] = !render.coverage[i]; break;
        default: break;
      }
    }
    const double abs_tolerance = rng() % 8 == 0 ? 0.0 : std::pow(10.0, -6 + 5 * unit(rng));
    const ComparisonThresholds t{abs_tolerance, 2 * abs_tolerance, rng() % 2 ? 0.0 : 1e-3 * unit(rng),
                                 rng() % 2 ? 0.0 : 1e-3 * unit(rng)};
    const Comparison c = compare_images(render, ref, t, rng() % 2 ? disc_area(20) : 0);
    const std::vector<std::string> again = failed_checks(cell_metrics(c), t);
    EXPECT_EQ(again.empty(), c.pass) << "trial " << trial << ": " << c.reason << " | "
                                     << (again.empty() ? "" : again.front());
    (c.pass ? passes : fails)++;
  }
  EXPECT_GT(passes, 40);
  EXPECT_GT(fails, 40);
}

TEST(VerdictFromMetrics, AnEditedMetricFails) {
  const ReferenceImage ref = disc_reference();
  const ComparisonThresholds t{1e-3, 2e-3, 0, 0};
  const Comparison c = compare_images(copy_of(ref), ref, t, disc_area(20));
  ASSERT_TRUE(c.pass) << c.reason;
  const CellMetrics honest = cell_metrics(c);
  EXPECT_TRUE(failed_checks(honest, t).empty());
  for (auto edit : {+[](CellMetrics& m) { m.max_abs = 80; }, +[](CellMetrics& m) { m.bad_pixels = 500; },
                    +[](CellMetrics& m) { m.nonfinite_mismatch = 7; }, +[](CellMetrics& m) { m.covered_pixels /= 2; },
                    +[](CellMetrics& m) { m.silhouette_max_abs = 0.5; }, +[](CellMetrics& m) { m.tolerance_share = 3; },
                    +[](CellMetrics& m) { m.interior_pixels = 0; }}) {
    CellMetrics m = honest;
    edit(m);
    EXPECT_FALSE(failed_checks(m, t).empty());
  }
}

}  // namespace
}  // namespace shaderbed
