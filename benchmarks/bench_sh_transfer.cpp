// Google Benchmark: the shadowed SH transfer precomputation (sh/Transfer.h) of a torus on a
// floor, in rays per second, on one thread and on all of them; and Embree's packet
// occlusion query against single rays, which decided that the transfer uses packets.
// Printed, never asserted: a shared, noisy machine.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <thread>

#include <tbb/global_control.h>

#include "sh/Basis.h"
#include "sh/Sampling.h"
#include "sh/Transfer.h"

namespace sh {
namespace {

constexpr double pi = std::numbers::pi;

// glutSolidTorus's parametrisation: `rings` steps of θ around the main axis (z, as GLUT),
// `sides` steps of φ around the tube; the seam vertices are shared, not duplicated.
TransferMesh torus(double tube_radius, double ring_radius, int sides, int rings) {
  TransferMesh mesh;
  mesh.albedo = glm::dvec3(0.8, 0.6, 0.4);
  for (int i = 0; i < rings; ++i) {
    const double theta = 2.0 * pi * i / rings;
    for (int j = 0; j < sides; ++j) {
      const double phi = 2.0 * pi * j / sides;
      const glm::dvec3 normal(std::cos(phi) * std::cos(theta), std::cos(phi) * std::sin(theta), std::sin(phi));
      const double distance = ring_radius + tube_radius * std::cos(phi);
      mesh.positions.emplace_back(distance * std::cos(theta), distance * std::sin(theta), tube_radius * std::sin(phi));
      mesh.normals.push_back(normal);
    }
  }
  const auto at = [&](int i, int j) { return static_cast<uint32_t>((i % rings) * sides + (j % sides)); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j)
      mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j), at(i, j + 1), at(i, j + 1), at(i + 1, j), at(i + 1, j + 1)});
  return mesh;
}

// The torus stands on its rim (GLUT's axis is z, the scene is y up), 1% of its size above
// a floor four times as wide.
TransferScene torus_on_floor(int tessellation) {
  const double tube = 0.3, ring = 0.7;
  auto scene = TransferScene::create({torus(tube, ring, tessellation, tessellation),
                                      ground_plane(-(tube + ring) - 0.01, 4.0, 32, glm::dvec3(0.6))});
  if (!scene) throw std::runtime_error(scene.error());
  return std::move(*scene);
}

// Rays one pass casts: one per vertex and sample above the vertex's horizon.
int64_t rays_per_pass(const TransferScene& scene, const std::vector<Sample>& samples) {
  int64_t rays = 0;
  for (const TransferMesh& mesh : scene.meshes())
    for (const glm::dvec3& n : mesh.normals)
      for (const Sample& s : samples) rays += glm::dot(n, from_sh_frame(s.direction)) > 0.0;
  return rays;
}

int thread_count(int64_t requested) {
  return requested > 0 ? static_cast<int>(requested) : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// Args: tessellation (torus rings = sides), grid (grid² samples), threads (0: all).
void BM_ShadowedTransfer(benchmark::State& state) {
  const TransferScene scene = torus_on_floor(static_cast<int>(state.range(0)));
  const TransferOptions options{.kind = TransferKind::shadowed, .bands = 4, .grid = static_cast<int>(state.range(1)), .seed = 1};
  const std::vector<Sample> samples = jittered_samples(options.grid, options.seed);
  const int64_t rays = rays_per_pass(scene, samples);
  const int threads = thread_count(state.range(2));
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(threads));
  for (auto _ : state) {
    auto transfer = compute_transfer(scene, options, samples);
    if (!transfer) state.SkipWithError(transfer.error().c_str());
    benchmark::DoNotOptimize(transfer);
  }
  state.counters["rays"] = benchmark::Counter(static_cast<double>(rays * state.iterations()), benchmark::Counter::kIsRate);
  state.counters["vertices"] = static_cast<double>(scene.vertex_count());
  state.counters["threads"] = threads;
}
BENCHMARK(BM_ShadowedTransfer)
    ->ArgNames({"tess", "grid", "threads"})
    ->Args({64, 100, 1})
    ->Args({64, 100, 0})
    ->Args({16, 10, 0})  // small: what ctest runs
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

// Occlusion alone, one thread: Arg 0 casts rtcOccluded1 per ray, 1 the packets of 16 that
// the transfer uses (same rays, same origins).
void BM_Occlusion(benchmark::State& state) {
  const TransferScene scene = torus_on_floor(32);
  const std::vector<Sample> samples = jittered_samples(40, 1);
  const TransferMesh& mesh = scene.meshes()[0];
  std::vector<std::vector<glm::vec3>> directions(mesh.positions.size());
  int64_t rays = 0;
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    for (const Sample& s : samples) {
      const glm::dvec3 d = from_sh_frame(s.direction);
      if (glm::dot(mesh.normals[v], d) > 0.0) directions[v].emplace_back(d);
    }
    rays += static_cast<int64_t>(directions[v].size());
  }
  std::vector<uint8_t> blocked;
  int64_t hits = 0;
  for (auto _ : state) {
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
      const glm::dvec3 origin = scene.ray_origin(mesh.positions[v], mesh.normals[v]);
      if (state.range(0) == 0) {
        for (const glm::vec3& d : directions[v]) hits += scene.occluded(origin, glm::dvec3(d));
      } else {
        blocked.resize(directions[v].size());
        scene.occluded(origin, directions[v], blocked);
        for (uint8_t b : blocked) hits += b;
      }
    }
  }
  benchmark::DoNotOptimize(hits);
  state.counters["rays"] = benchmark::Counter(static_cast<double>(rays * state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Occlusion)->ArgName("packets")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace sh

BENCHMARK_MAIN();
