// Google Benchmark: the image comparison at the suite's size. It runs once per cell
// (~1400 times in the default suite), so its cost per 256x256 image is printed here
// rather than asserted in a timed unit test (shared CI machines are noisy).
#include <benchmark/benchmark.h>

#include "CompareTestSupport.h"
#include "compare/ConventionFit.h"
#include "compare/ImageComparison.h"

namespace shaderbed {
namespace {

// `classified`: the reference's pixel classes computed once outside the loop, as the
// runner does for the ~10 renders of a group that share one reference.
void compare(benchmark::State& state, bool classified) {
  const int size = int(state.range(0));
  const double radius = 0.35 * size, centre = 0.5 * size;
  const ReferenceImage ref = compare_test::disc_reference(radius, centre, centre, size);
  // Slightly larger, so the silhouette band and the interior both have work to do.
  const Image render = compare_test::disc_render(radius + 0.3, centre, centre, size);
  const double area = 3.14159265358979 * radius * radius;
  const std::vector<PixelClass> classes = classify_pixels(ref);
  for (auto _ : state) {
    Comparison c = compare_images(render, ref, {1e-4, 0.1}, area, classified ? &classes : nullptr);
    benchmark::DoNotOptimize(c);
  }
  state.SetItemsProcessed(state.iterations() * int64_t(size) * size);
}
void BM_CompareImages(benchmark::State& state) { compare(state, false); }
void BM_CompareImagesClassified(benchmark::State& state) { compare(state, true); }
BENCHMARK(BM_CompareImages)->Arg(64)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CompareImagesClassified)->Arg(256)->Unit(benchmark::kMillisecond);

// A failing cell's explanations (every image-space fit, and `counterfactuals` re-rendered
// references), beside the comparison above: read the two as a ratio, measured in one run.
void BM_ExplainDifference(benchmark::State& state) {
  const int size = int(state.range(0));
  const double radius = 0.35 * size, centre = 0.5 * size;
  const ReferenceImage ref = compare_test::disc_reference(radius, centre, centre, size);
  const Image render = compare_test::disc_render(radius, centre, centre, size, [](double v, int) { return v * 3.14159265358979; });
  const std::vector<PixelClass> classes = classify_pixels(ref);
  const std::vector<ReferenceImage> images(size_t(state.range(1)), ref);
  std::vector<Counterfactual> counterfactuals;
  for (const ReferenceImage& image : images) counterfactuals.push_back({"counterfactual", "a copy", &image});
  const ConventionEvidence evidence{.counterfactuals = counterfactuals, .parameters = {{"power", 7}}};
  for (auto _ : state) {
    std::vector<ConventionFit> fits = explain_difference(render, ref, classes, {1e-5, 1e-4}, evidence);
    benchmark::DoNotOptimize(fits);
  }
  state.SetItemsProcessed(state.iterations() * int64_t(size) * size);
}
BENCHMARK(BM_ExplainDifference)->Args({256, 0})->Args({256, 3})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace shaderbed

BENCHMARK_MAIN();
