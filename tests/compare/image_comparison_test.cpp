// compare_images on synthetic pixel data: masks, thresholds, non-finite values, blank
// and degenerate coverage, smallest passing thresholds, value counts and masks.
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "TestThresholds.h"
#include "CompareTestSupport.h"
#include "compare/ImageComparison.h"
#include "compare/ImageFiles.h"

namespace shaderbed {
namespace {

using namespace compare_test;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
using test::kThresholds;

// An interior and a silhouette pixel of the default disc (radius 20 at (32, 32)).
constexpr int kInteriorX = 32, kInteriorY = 32;
constexpr int kBandX = 12, kBandY = 32;   // centre 12.5: inside (r = 19.5), neighbour at 11.5 outside

TEST(Classify, SeparableSumsMatchBruteForce) {
  std::mt19937 rng(7);
  for (int size : {1, 2, 3, 17}) {
    ReferenceImage ref{size, size + 1, std::vector<double>(size_t(size) * (size + 1) * 4),
                       std::vector<uint8_t>(size_t(size) * (size + 1))};
    for (uint8_t& c : ref.coverage) c = rng() % 3 != 0;
    const auto classes = classify_pixels(ref);
    for (int y = 0; y < ref.height; ++y)
      for (int x = 0; x < ref.width; ++x) {
        int covered = 0, seen = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= ref.width || ny >= ref.height) continue;
            ++seen;
            covered += ref.coverage[size_t(ny) * ref.width + nx];
          }
        const size_t i = size_t(y) * ref.width + x;
        const PixelClass want = covered == 0                            ? PixelClass::background
                                : covered == seen && ref.coverage[i] ? PixelClass::interior
                                                                     : PixelClass::silhouette;
        EXPECT_EQ(classes[i], want) << size << " " << x << "," << y;
      }
  }
}

TEST(Classify, FixturePixelsAreWhereTheTestsSayTheyAre) {
  const auto classes = classify_pixels(disc_reference());
  EXPECT_EQ(classes[size_t(kInteriorY) * kSize + kInteriorX], PixelClass::interior);
  EXPECT_EQ(classes[size_t(kBandY) * kSize + kBandX], PixelClass::silhouette);
  EXPECT_EQ(disc_reference().coverage[size_t(kBandY) * kSize + kBandX], 1);
  EXPECT_EQ(classes[0], PixelClass::background);
}

TEST(Compare, IdenticalRenderPassesWithZeroSmallestThresholds) {
  const ReferenceImage ref = disc_reference();
  const Comparison c = compare_images(copy_of(ref), ref, kThresholds, disc_area(20));
  EXPECT_TRUE(c.pass) << c.reason;
  EXPECT_EQ(c.reason, "");
  EXPECT_EQ(c.covered_pixels, c.reference_covered_pixels);
  EXPECT_GT(c.interior.pixels, 1000u);
  EXPECT_GT(c.silhouette.pixels, 200u);
  EXPECT_LT(c.min_passing_interior, 1e-7);   // float rounding of the double reference
  EXPECT_EQ(c.min_passing_interior, c.interior.max_abs);
  EXPECT_EQ(c.min_passing_silhouette, c.silhouette.max_abs);
  EXPECT_FALSE(c.blank);
  EXPECT_FALSE(c.degenerate);
  EXPECT_EQ(c.nonfinite, 0u);
}

TEST(Compare, SmallestPassingThresholdsAreTheMeasuredMaxima) {
  const ReferenceImage ref = disc_reference();
  Image render = copy_of(ref);
  render.pixel(kInteriorX, kInteriorY)[1] += 0.003f;
  render.pixel(kInteriorX + 3, kInteriorY - 2)[0] -= 0.001f;
  render.pixel(kBandX, kBandY)[2] += 0.5f;   // no neighbour is within 0.49
  const Comparison c = compare_images(render, ref, kThresholds);
  EXPECT_FALSE(c.pass);
  const double interior_error = std::abs(double(render.pixel(kInteriorX, kInteriorY)[1]) -
                                         ref.rgba[(size_t(kInteriorY) * kSize + kInteriorX) * 4 + 1]);
  EXPECT_EQ(c.interior.max_abs, interior_error);
  EXPECT_EQ(c.min_passing_interior, interior_error);
  EXPECT_GT(c.min_passing_silhouette, 0.48);
  EXPECT_EQ(c.min_passing_silhouette, c.silhouette.max_abs);
  EXPECT_NE(c.reason.find("2 interior pixels over 1e-05"), std::string::npos) << c.reason;
  EXPECT_NE(c.reason.find("1 silhouette pixels over 0.01"), std::string::npos) << c.reason;

  // Exactly those thresholds pass; anything tighter in either region fails.
  const ComparisonThresholds exact{c.min_passing_interior, c.min_passing_silhouette};
  EXPECT_TRUE(compare_images(render, ref, exact).pass);
  EXPECT_FALSE(compare_images(render, ref, {std::nextafter(exact.interior_max_abs, 0.0), exact.silhouette_max_abs}).pass);
  EXPECT_FALSE(compare_images(render, ref, {exact.interior_max_abs, std::nextafter(exact.silhouette_max_abs, 0.0)}).pass);
}

TEST(Compare, BlankRenderFails) {
  const ReferenceImage ref = disc_reference();
  const Image blank(kSize, kSize);
  const Comparison c = compare_images(blank, ref, {1e30, 1e30}, disc_area(20));
  EXPECT_FALSE(c.pass);
  EXPECT_TRUE(c.blank);
  EXPECT_EQ(c.covered_pixels, 0u);
  EXPECT_EQ(c.reason.rfind("blank image: coverage 0 px, reference ", 0), 0u) << c.reason;
  EXPECT_NE(c.reason.find("expected ≈1257 px"), std::string::npos) << c.reason;
  EXPECT_EQ(c.min_passing_interior, kInf);
  EXPECT_EQ(c.min_passing_silhouette, kInf);
}

TEST(Compare, HalfSizeRenderFailsOnItsCoverage) {
  const ReferenceImage ref = disc_reference();
  const Image half = disc_render(20.0 / std::sqrt(2.0));   // half the area
  const Comparison c = compare_images(half, ref, {1e30, 1e30}, disc_area(20));
  EXPECT_FALSE(c.pass);
  EXPECT_TRUE(c.degenerate);
  EXPECT_FALSE(c.blank);
  EXPECT_NEAR(double(c.covered_pixels), disc_area(20) / 2, 20);
  EXPECT_EQ(c.reason.rfind("coverage " + std::to_string(c.covered_pixels) + " px, reference " +
                               std::to_string(c.reference_covered_pixels) + " px, expected ≈1257 px (allowed ±",
                           0),
            0u)
      << c.reason;
  EXPECT_EQ(c.min_passing_interior, kInf);
}

TEST(Compare, ScaledRenderFailsButSubPixelEdgeDifferencesPass) {
  const ReferenceImage ref = disc_reference();
  // A rasteriser whose edges land a fifth of a pixel further out: a legitimate difference.
  const Comparison slightly = compare_images(disc_render(20.2), ref, kThresholds, disc_area(20));
  EXPECT_TRUE(slightly.pass) << slightly.reason;
  EXPECT_FALSE(slightly.degenerate);
  EXPECT_GT(slightly.covered_pixels, slightly.reference_covered_pixels);
  // 8 % larger (17 % more area): the count is off by more than the allowance.
  const Comparison scaled = compare_images(disc_render(21.6), ref, {1e30, 1e30}, disc_area(20));
  EXPECT_FALSE(scaled.pass);
  EXPECT_TRUE(scaled.degenerate) << scaled.reason;
}

TEST(Compare, OnePercentScaleFailsAt256) {
  // A disc the size of the scene's sphere at 256 px: a 1 % larger render fails on its
  // count alone (huge thresholds), a quarter pixel of edge growth does not.
  const ReferenceImage ref = disc_reference(70, 128, 128, 256);
  const Comparison scaled = compare_images(disc_render(70.7, 128, 128, 256), ref, {1e30, 1e30}, disc_area(70));
  EXPECT_TRUE(scaled.degenerate) << scaled.reason;
  EXPECT_FALSE(scaled.pass);
  const Comparison grown = compare_images(disc_render(70.25, 128, 128, 256), ref, {1e30, 1e30}, disc_area(70));
  EXPECT_FALSE(grown.degenerate) << grown.reason;
  EXPECT_TRUE(grown.pass) << grown.reason;
}

TEST(Compare, CoverageAllowanceFollowsTheOutline) {
  const ReferenceImage ref = disc_reference();
  const Comparison c = compare_images(copy_of(ref), ref, kThresholds);
  EXPECT_EQ(c.allowed_coverage_difference, 8 + c.silhouette.pixels / 8);
  // The band is about 8/pi pixels per pixel of outline: the allowance is 8 px plus
  // about a third of the perimeter.
  EXPECT_NEAR(double(c.allowed_coverage_difference), 8 + 2 * std::numbers::pi * 20 / 3, 4);
  EXPECT_EQ(coverage_allowance(0), 8u);
  EXPECT_EQ(coverage_allowance(1000), 133u);
}

TEST(Compare, ShiftedRenderFailsOnCoverageNotOnCount) {
  const ReferenceImage ref = disc_reference();
  const Image shifted = disc_render(20, 35, 32);
  const Comparison c = compare_images(shifted, ref, {1e30, 1e30}, disc_area(20));
  EXPECT_FALSE(c.pass);
  EXPECT_FALSE(c.degenerate);
  EXPECT_GT(c.coverage_mismatch, 50u);
  EXPECT_NE(c.reason.find("coverage differs at"), std::string::npos) << c.reason;
  EXPECT_EQ(c.min_passing_interior, kInf);
  // One pixel: coverage holds (the band absorbs it) but the shading moved with it.
  const Image nudged = disc_render(20, 33, 32, kSize, [](double v, int) { return v + 0.002; });
  const Comparison n = compare_images(nudged, ref, kThresholds, disc_area(20));
  EXPECT_FALSE(n.pass);
  EXPECT_EQ(n.coverage_mismatch, 0u);
  EXPECT_GT(n.interior.bad_pixels, 100u);
}

TEST(Compare, ReferenceOffTheExpectedAreaFailsEvenWhenTheRenderAgrees) {
  // Both images 30 % too large (a wrong transform on both sides): only the area sees it.
  const ReferenceImage ref = disc_reference(26);
  const Image render = copy_of(ref);
  EXPECT_TRUE(compare_images(render, ref, kThresholds).pass);
  const Comparison c = compare_images(render, ref, kThresholds, disc_area(20));
  EXPECT_FALSE(c.pass);
  EXPECT_TRUE(c.degenerate);
  EXPECT_NE(c.reason.find("expected ≈1257 px"), std::string::npos) << c.reason;
  EXPECT_NE(c.reason.find("the reference"), std::string::npos) << c.reason;
  EXPECT_EQ(c.expected_area, disc_area(20));
}

TEST(Compare, NaNInTheInteriorFailsWhateverTheTolerance) {
  const ReferenceImage ref = disc_reference();
  Image render = copy_of(ref);
  render.pixel(kInteriorX, kInteriorY)[2] = kNaN;
  const Comparison c = compare_images(render, ref, {1e30, 1e30});
  EXPECT_FALSE(c.pass);
  EXPECT_EQ(c.nonfinite, 1u);
  EXPECT_EQ(c.nonfinite_mismatch, 1u);
  EXPECT_EQ(c.render_values.nan, 1u);
  EXPECT_EQ(c.reference_values.nan, 0u);
  EXPECT_NE(c.reason.find("1 pixels NaN/Inf where the reference is finite or the reverse (fails at any tolerance)"),
            std::string::npos)
      << c.reason;
  EXPECT_EQ(c.min_passing_interior, kInf);
  EXPECT_EQ(c.min_passing_silhouette, kInf);
  EXPECT_EQ(c.interior.max_abs, kInf);
  EXPECT_EQ(c.error.pixel(kInteriorX, kInteriorY)[2], float(kInf));
}

TEST(Compare, InfinityInsteadOfNaNIsAMismatchToo) {
  ReferenceImage ref = disc_reference();
  ref.rgba[(size_t(kInteriorY) * kSize + kInteriorX) * 4] = std::numeric_limits<double>::quiet_NaN();
  Image render = copy_of(ref);
  render.pixel(kInteriorX, kInteriorY)[0] = std::numeric_limits<float>::infinity();
  const Comparison c = compare_images(render, ref, {1e30, 1e30});
  EXPECT_FALSE(c.pass);
  EXPECT_EQ(c.nonfinite_mismatch, 1u);
  EXPECT_EQ(c.render_values.pos_inf, 1u);
  EXPECT_EQ(c.reference_values.nan, 1u);
}

TEST(Compare, NaNInBothAtTheSamePixelIsReportedButNotAMismatch) {
  ReferenceImage ref = disc_reference();
  ref.rgba[(size_t(kInteriorY) * kSize + kInteriorX) * 4 + 1] = std::numeric_limits<double>::quiet_NaN();
  Image render = copy_of(ref);
  ASSERT_TRUE(std::isnan(render.pixel(kInteriorX, kInteriorY)[1]));
  const Comparison c = compare_images(render, ref, kThresholds);
  EXPECT_TRUE(c.pass) << c.reason;
  EXPECT_EQ(c.nonfinite, 1u);
  EXPECT_EQ(c.nonfinite_mismatch, 0u);
  EXPECT_EQ(c.render_values.nan, 1u);
  EXPECT_EQ(c.reference_values.nan, 1u);
  EXPECT_EQ(c.error.pixel(kInteriorX, kInteriorY)[1], 0.0f);
  EXPECT_LT(c.min_passing_interior, 1e-7);
}

TEST(Compare, NaNOnTheSilhouetteFailsWhateverTheTolerance) {
  const ReferenceImage ref = disc_reference();
  Image render = copy_of(ref);
  render.pixel(kBandX, kBandY)[0] = kNaN;
  const Comparison c = compare_images(render, ref, {1e30, 1e30});
  EXPECT_FALSE(c.pass);
  EXPECT_EQ(c.nonfinite_mismatch, 1u);
  EXPECT_EQ(c.silhouette.bad_pixels, 1u);
  EXPECT_EQ(c.min_passing_silhouette, kInf);
}

TEST(Compare, ReferenceNaNOnTheSilhouetteNeedsANaNNearbyInTheRender) {
  ReferenceImage ref = disc_reference();
  ref.rgba[(size_t(kBandY) * kSize + kBandX) * 4] = std::numeric_limits<double>::quiet_NaN();
  Image finite = copy_of(ref);
  finite.pixel(kBandX, kBandY)[0] = 0.3f;
  const Comparison c = compare_images(finite, ref, {1e30, 1e30});
  EXPECT_FALSE(c.pass);
  EXPECT_EQ(c.nonfinite_mismatch, 1u);
  // The render's NaN one pixel over (an edge shift) is a match.
  Image shifted = finite;
  shifted.pixel(kBandX + 1, kBandY)[0] = kNaN;
  ref.rgba[(size_t(kBandY) * kSize + kBandX + 1) * 4] = std::numeric_limits<double>::quiet_NaN();
  const Comparison s = compare_images(shifted, ref, kThresholds);
  EXPECT_EQ(s.nonfinite_mismatch, 0u) << s.reason;
}

TEST(Compare, ValueCountsCountPixelsPerClass) {
  ReferenceImage ref = disc_reference();
  Image render = copy_of(ref);
  auto set = [&](int x, int y, float r, float g, float b) {
    float* p = render.pixel(x, y);
    p[0] = r, p[1] = g, p[2] = b;
  };
  const float inf = std::numeric_limits<float>::infinity();
  set(30, 30, kNaN, kNaN, 0.5f);      // one NaN pixel (two channels)
  set(31, 30, inf, 0.5f, 0.5f);       // +Inf
  set(32, 30, 0.5f, -inf, 0.5f);      // -Inf
  set(33, 30, -0.25f, 0.5f, 0.5f);    // negative
  set(34, 30, 0.5f, 0.5f, 1.5f);      // above one
  set(35, 30, -1.0f, 2.0f, kNaN);     // negative, above one and NaN at once
  set(36, 30, 0.0f, 1.0f, 0.0f);      // the ends of [0, 1] are in range
  set(1, 1, kNaN, -1.0f, 5.0f);       // not drawn: not counted
  const ValueCounts v = count_values(render);
  EXPECT_EQ(v.nan, 2u);
  EXPECT_EQ(v.pos_inf, 1u);
  EXPECT_EQ(v.neg_inf, 1u);
  EXPECT_EQ(v.negative, 2u);
  EXPECT_EQ(v.above_one, 2u);
  const Comparison c = compare_images(render, ref, {1e30, 1e30});
  EXPECT_EQ(c.render_values.nan, v.nan);
  EXPECT_EQ(c.render_values.negative, v.negative);
  EXPECT_EQ(c.render_values.above_one, v.above_one);
  EXPECT_EQ(c.nonfinite, 4u);
  EXPECT_EQ(c.nonfinite_mismatch, 4u);
  EXPECT_EQ(c.reference_values.nan + c.reference_values.negative + c.reference_values.above_one, 0u);

  ref.rgba[(size_t(40) * kSize + 30) * 4 + 2] = -0.5;
  ref.rgba[(size_t(40) * kSize + 31) * 4 + 0] = -std::numeric_limits<double>::infinity();
  ref.rgba[(size_t(0) * kSize + 0) * 4 + 0] = -5;   // not covered
  const ValueCounts r = count_values(ref);
  EXPECT_EQ(r.negative, 1u);
  EXPECT_EQ(r.neg_inf, 1u);
  EXPECT_EQ(r.nan + r.pos_inf + r.above_one, 0u);
}

TEST(Compare, ValueMaskColoursEachClass) {
  Image im(8, 1);
  const float inf = std::numeric_limits<float>::infinity();
  const float values[8][3] = {{kNaN, 0, 0}, {inf, 0, 0}, {-inf, 0, 0}, {-0.5f, 0, 0},
                              {2, 0, 0},    {0.5f, 0.5f, 0.5f}, {kNaN, -1, 2}, {1, 1, 1}};
  for (int x = 0; x < 8; ++x) {
    for (int c = 0; c < 3; ++c) im.pixel(x, 0)[c] = values[x][c];
    im.coverage[x] = x != 7;
  }
  const Image mask = value_mask(im);
  auto colour = [&](int x) { return std::array<float, 3>{mask.pixel(x, 0)[0], mask.pixel(x, 0)[1], mask.pixel(x, 0)[2]}; };
  EXPECT_EQ(colour(0), (std::array<float, 3>{1, 0, 1}));   // NaN magenta
  EXPECT_EQ(colour(1), (std::array<float, 3>{1, 0, 0}));   // +Inf red
  EXPECT_EQ(colour(2), (std::array<float, 3>{0, 0, 1}));   // -Inf blue
  EXPECT_EQ(colour(3), (std::array<float, 3>{0, 1, 1}));   // negative cyan
  EXPECT_EQ(colour(4), (std::array<float, 3>{1, 1, 0}));   // above one yellow
  EXPECT_EQ(colour(6), (std::array<float, 3>{1, 0, 1}));   // NaN wins over the others
  const auto grey = colour(5);
  EXPECT_EQ(grey[0], grey[1]);
  EXPECT_LT(grey[0], 0.35f);
  EXPECT_EQ(mask.coverage, im.coverage);

  // The reference's mask, and the PNG the runner writes next to the renders.
  ReferenceImage ref{2, 1, {std::nan(""), 0, 0, 1, 0.5, 0.5, 0.5, 1}, {1, 1}};
  const Image ref_mask = value_mask(ref);
  EXPECT_EQ(ref_mask.pixel(0, 0)[0], 1.0f);
  EXPECT_EQ(ref_mask.pixel(0, 0)[1], 0.0f);
  const auto dir = std::filesystem::temp_directory_path() / "shaderbed_compare_test";
  const std::string path = (dir / "values.png").string();
  std::filesystem::remove(path);
  ASSERT_TRUE(write_png(path, mask).has_value());
  EXPECT_GT(std::filesystem::file_size(path), 0u);
  std::filesystem::remove_all(dir);
}

TEST(Compare, UniformRenderIsNamedBlankOutput) {
  const ReferenceImage ref = disc_reference();
  const Image black = disc_render(20, 32, 32, kSize, [](double, int) { return 0.0; });
  const Comparison c = compare_images(black, ref, kThresholds, disc_area(20));
  EXPECT_FALSE(c.pass);
  EXPECT_TRUE(c.uniform);
  EXPECT_NE(c.reason.find("blank output: every drawn pixel is (0, 0, 0)"), std::string::npos) << c.reason;
  // A uniform reference (an ambient-only model) makes a uniform render correct.
  ReferenceImage flat = ref;
  for (size_t i = 0; i < flat.coverage.size(); ++i)
    for (int c = 0; c < 3; ++c) flat.rgba[i * 4 + c] = 0;
  const Comparison ok = compare_images(black, flat, kThresholds, disc_area(20));
  EXPECT_TRUE(ok.pass) << ok.reason;
  EXPECT_TRUE(ok.uniform);
}

TEST(Compare, SizeMismatchFails) {
  const Comparison c = compare_images(Image(32, 32), disc_reference(), kThresholds);
  EXPECT_FALSE(c.pass);
  EXPECT_EQ(c.reason, "render is 32x32, reference 64x64");
  EXPECT_EQ(c.min_passing_interior, kInf);
}

TEST(Compare, EmptyReferenceFails) {
  const ReferenceImage empty{kSize, kSize, std::vector<double>(size_t(kSize) * kSize * 4),
                             std::vector<uint8_t>(size_t(kSize) * kSize)};
  const Comparison c = compare_images(Image(kSize, kSize), empty, kThresholds);
  EXPECT_FALSE(c.pass);
  EXPECT_NE(c.reason.find("reference covers no interior pixels"), std::string::npos);
  EXPECT_FALSE(c.blank);   // nothing to draw: not the render's fault
}

TEST(Compare, CellMetricsCarryEveryNumber) {
  const ReferenceImage ref = disc_reference();
  Image render = copy_of(ref);
  render.pixel(kInteriorX, kInteriorY)[0] = 3.0f;
  render.pixel(kInteriorX, kInteriorY + 1)[1] = kNaN;
  const Comparison c = compare_images(render, ref, kThresholds, 1250);
  const CellMetrics m = cell_metrics(c);
  EXPECT_EQ(m.max_abs, c.interior.max_abs);
  EXPECT_EQ(m.rmse, c.interior.rmse);
  EXPECT_EQ(m.psnr, c.psnr);
  EXPECT_EQ(m.bad_pixels, c.interior.bad_pixels + c.silhouette.bad_pixels);
  EXPECT_EQ(m.bad_pixels, 2u);
  EXPECT_EQ(m.nonfinite, 1u);
  EXPECT_EQ(m.nonfinite_mismatch, 1u);
  EXPECT_EQ(m.coverage_mismatch, 0u);
  EXPECT_EQ(m.silhouette_max_abs, c.silhouette.max_abs);
  EXPECT_EQ(m.interior_pixels, c.interior.pixels);
  EXPECT_EQ(m.silhouette_pixels, c.silhouette.pixels);
  EXPECT_EQ(m.covered_pixels, c.covered_pixels);
  EXPECT_EQ(m.reference_covered_pixels, c.reference_covered_pixels);
  EXPECT_EQ(m.expected_area, 1250);
  EXPECT_EQ(m.min_passing_interior, kInf);
  EXPECT_EQ(m.render_values.nan, 1u);
  EXPECT_EQ(m.render_values.above_one, 1u);
  EXPECT_TRUE(std::isfinite(m.rmse));   // the NaN pixel is left out of the RMSE
  EXPECT_GT(m.rmse, 0);
}

}  // namespace
}  // namespace shaderbed
