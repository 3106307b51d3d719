// Google Benchmark: the reference shading every pixel of a 512x512 sphere, per model, so a
// change to reference/models can be compared before and after in one run of this binary
// (printed, never asserted: a shared, noisy machine).
#include <benchmark/benchmark.h>

#include <glm/ext/matrix_transform.hpp>

#include "UvSphere.h"
#include "reference/Reference.h"

namespace reference {
namespace {

void BM_ReferencePerPixel(benchmark::State& state, const std::string& model) {
  Scene scene;
  scene.mesh = test::uv_sphere(64, 32);
  scene.world = glm::scale(glm::dmat4(1.0), glm::dvec3(30.0));
  scene.width = scene.height = 512;
  const Params params = *default_params(model);
  for (auto _ : state) {
    auto image = render(scene, model, Mode::per_pixel, params);
    benchmark::DoNotOptimize(image);
  }
  state.SetItemsProcessed(state.iterations() * int64_t(scene.width) * scene.height);
}

const int registered = [] {
  for (const std::string& model : model_names())
    benchmark::RegisterBenchmark(("BM_ReferencePerPixel/" + model).c_str(), BM_ReferencePerPixel, model)
        ->Unit(benchmark::kMillisecond);
  return 0;
}();

}  // namespace
}  // namespace reference

BENCHMARK_MAIN();
