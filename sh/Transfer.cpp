#include "sh/Transfer.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "sh/Basis.h"

namespace sh {

namespace {

constexpr int max_bands = 20;      // 400 coefficients; D3DX stopped at order 6
constexpr int max_grid = 1000;     // a million samples per vertex
constexpr int max_bounces = 16;

// The samples as every vertex uses them: unit scene directions (double for cosines, float
// for Embree), weights, and the basis at each direction in the SH frame, computed once.
struct SampleTable {
  int coefficients = 0;
  std::vector<glm::dvec3> directions;
  std::vector<glm::vec3> directions_f;
  std::vector<double> weights;
  std::vector<double> basis;  // sample-major, `coefficients` each

  std::span<const double> basis_of(size_t s) const {
    return std::span<const double>(basis).subspan(s * static_cast<size_t>(coefficients), static_cast<size_t>(coefficients));
  }
};

std::expected<SampleTable, std::string> make_table(std::span<const Sample> samples, int bands) {
  if (samples.empty()) return std::unexpected(std::string("transfer: no samples"));
  SampleTable table;
  table.coefficients = coefficient_count(bands);
  table.directions.reserve(samples.size());
  table.basis.resize(samples.size() * static_cast<size_t>(table.coefficients));
  for (size_t s = 0; s < samples.size(); ++s) {
    const double length = glm::length(samples[s].direction);
    if (!std::isfinite(length) || length == 0.0 || !std::isfinite(samples[s].weight))
      return std::unexpected(fmt::format("transfer: sample {} has no direction or a non-finite weight", s));
    // Samples come in the SH frame (Sampling.h); rays and normals live in the scene's.
    const glm::dvec3 in_sh_frame = samples[s].direction / length;
    const glm::dvec3 d = from_sh_frame(in_sh_frame);
    table.directions.push_back(d);
    table.directions_f.emplace_back(d);
    table.weights.push_back(samples[s].weight);
    basis_all(bands, in_sh_frame, std::span<double>(table.basis).subspan(s * static_cast<size_t>(table.coefficients),
                                                                          static_cast<size_t>(table.coefficients)));
  }
  return table;
}

std::expected<void, std::string> check(const TransferOptions& options, bool sampled) {
  if (options.bands < 1 || options.bands > max_bands)
    return std::unexpected(fmt::format("transfer: bands {} outside [1, {}]", options.bands, max_bands));
  if (sampled && (options.grid < 1 || options.grid > max_grid))
    return std::unexpected(fmt::format("transfer: grid {} outside [1, {}]", options.grid, max_grid));
  if (options.kind == TransferKind::interreflected && (options.bounces < 0 || options.bounces > max_bounces))
    return std::unexpected(fmt::format("transfer: bounces {} outside [0, {}]", options.bounces, max_bounces));
  return {};
}

// Vertices of all meshes as one range, for one parallel loop over the whole scene.
struct VertexRange {
  std::vector<size_t> starts;  // first global vertex of each mesh, then the total

  explicit VertexRange(const TransferScene& scene) {
    size_t total = 0;
    for (const TransferMesh& mesh : scene.meshes()) {
      starts.push_back(total);
      total += mesh.positions.size();
    }
    starts.push_back(total);
  }
  size_t total() const { return starts.back(); }
  std::pair<size_t, size_t> locate(size_t global) const {
    const auto mesh = static_cast<size_t>(std::upper_bound(starts.begin(), starts.end(), global) - starts.begin()) - 1;
    return {mesh, global - starts[mesh]};
  }
};

// Serialises the caller's callback and keeps `done` increasing across worker threads.
class ProgressCounter {
 public:
  ProgressCounter(const TransferProgress& callback, size_t total, size_t done = 0)
      : callback_(callback), total_(total), done_(done) {}
  void add(size_t finished) {
    if (!callback_) return;
    std::lock_guard lock(mutex_);
    done_ += finished;
    callback_(done_, total_);
  }

 private:
  const TransferProgress& callback_;
  size_t total_;
  size_t done_;
  std::mutex mutex_;
};

// Per-task scratch, reused across the vertices of one chunk.
struct Scratch {
  std::vector<uint32_t> active;     // samples above the vertex's horizon
  std::vector<double> cosines;
  std::vector<glm::vec3> directions;
  std::vector<uint8_t> blocked;
  std::vector<RayHit> hits;
  std::vector<double> sum;
  std::vector<glm::dvec3> sum_rgb;
};

// Samples with n·ω > 0, and their cosines: the only ones the clamped cosine keeps.
void gather_active(const SampleTable& table, const glm::dvec3& normal, Scratch& scratch) {
  scratch.active.clear();
  scratch.cosines.clear();
  scratch.directions.clear();
  for (size_t s = 0; s < table.directions.size(); ++s) {
    const double c = glm::dot(normal, table.directions[s]);
    if (c > 0.0) {
      scratch.active.push_back(static_cast<uint32_t>(s));
      scratch.cosines.push_back(c);
      scratch.directions.push_back(table.directions_f[s]);
    }
  }
}

void direct_vertex(const TransferScene& scene, const SampleTable& table, const TransferMesh& mesh, size_t v, bool shadowed,
                   Scratch& scratch, std::span<glm::dvec3> out) {
  const glm::dvec3& normal = mesh.normals[v];
  gather_active(table, normal, scratch);
  const size_t count = scratch.active.size();
  scratch.blocked.assign(count, 0);
  if (shadowed) scene.occluded(scene.ray_origin(mesh.positions[v], normal), scratch.directions, scratch.blocked);
  // One scalar sum (the transfer is the same function in every channel); albedo at the end.
  scratch.sum.assign(static_cast<size_t>(table.coefficients), 0.0);
  for (size_t k = 0; k < count; ++k) {
    if (scratch.blocked[k]) continue;
    const size_t s = scratch.active[k];
    const double scale = table.weights[s] * scratch.cosines[k];
    const std::span<const double> y = table.basis_of(s);
    for (size_t i = 0; i < y.size(); ++i) scratch.sum[i] += scale * y[i];
  }
  const glm::dvec3 rho = mesh.albedo * std::numbers::inv_pi;
  for (size_t i = 0; i < out.size(); ++i) out[i] = rho * scratch.sum[i];
}

void bounce_vertex(const TransferScene& scene, const SampleTable& table, std::span<const VertexTransfer> previous,
                   const TransferMesh& mesh, size_t v, Scratch& scratch, std::span<glm::dvec3> out) {
  const glm::dvec3& normal = mesh.normals[v];
  gather_active(table, normal, scratch);
  const size_t count = scratch.active.size();
  scratch.hits.resize(count);
  scene.closest_hits(scene.ray_origin(mesh.positions[v], normal), scratch.directions, scratch.hits);
  const size_t n = static_cast<size_t>(table.coefficients);
  scratch.sum_rgb.assign(n, glm::dvec3(0.0));
  for (size_t k = 0; k < count; ++k) {
    const RayHit& hit = scratch.hits[k];
    if (!hit.hit()) continue;  // the distant light, already in the direct term
    const glm::dvec3& direction = table.directions[scratch.active[k]];
    // The back of a surface: its transfer is for the front side, so nothing comes out.
    if (glm::dot(scene.hit_normal(hit), direction) >= 0.0) continue;
    const size_t hit_mesh = static_cast<size_t>(hit.mesh);
    const uint32_t* corner = &scene.meshes()[hit_mesh].indices[3 * static_cast<size_t>(hit.triangle)];
    const std::vector<glm::dvec3>& from = previous[hit_mesh].coefficients;
    const double scale = table.weights[scratch.active[k]] * scratch.cosines[k];
    const double b0 = scale * (1.0 - static_cast<double>(hit.u) - static_cast<double>(hit.v));
    const double b1 = scale * static_cast<double>(hit.u);
    const double b2 = scale * static_cast<double>(hit.v);
    const glm::dvec3* t0 = &from[corner[0] * n];
    const glm::dvec3* t1 = &from[corner[1] * n];
    const glm::dvec3* t2 = &from[corner[2] * n];
    for (size_t i = 0; i < n; ++i) scratch.sum_rgb[i] += b0 * t0[i] + b1 * t1[i] + b2 * t2[i];
  }
  const glm::dvec3 rho = mesh.albedo * std::numbers::inv_pi;
  for (size_t i = 0; i < n; ++i) out[i] = rho * scratch.sum_rgb[i];
}

std::vector<VertexTransfer> allocate(const TransferScene& scene, int bands) {
  std::vector<VertexTransfer> result;
  for (const TransferMesh& mesh : scene.meshes())
    result.push_back({bands, std::vector<glm::dvec3>(mesh.positions.size() * static_cast<size_t>(coefficient_count(bands)))});
  return result;
}

// Runs `kernel(mesh, vertex, scratch, out)` for every vertex of the scene in parallel.
template <typename Kernel>
std::vector<VertexTransfer> for_each_vertex(const TransferScene& scene, int bands, ProgressCounter& progress,
                                            const Kernel& kernel) {
  std::vector<VertexTransfer> result = allocate(scene, bands);
  const VertexRange range(scene);
  const size_t n = static_cast<size_t>(coefficient_count(bands));
  // Small chunks: a vertex is hundreds to thousands of rays, so scheduling is cheap and
  // the progress callback is called often enough.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, range.total(), 4), [&](const tbb::blocked_range<size_t>& chunk) {
    Scratch scratch;
    for (size_t global = chunk.begin(); global != chunk.end(); ++global) {
      const auto [m, v] = range.locate(global);
      kernel(scene.meshes()[m], v, scratch, std::span<glm::dvec3>(result[m].coefficients).subspan(v * n, n));
    }
    progress.add(chunk.size());
  });
  return result;
}

std::vector<VertexTransfer> direct_pass(const TransferScene& scene, const SampleTable& table, int bands, bool shadowed,
                                        ProgressCounter& progress) {
  return for_each_vertex(scene, bands, progress, [&](const TransferMesh& mesh, size_t v, Scratch& scratch, std::span<glm::dvec3> out) {
    direct_vertex(scene, table, mesh, v, shadowed, scratch, out);
  });
}

std::vector<VertexTransfer> bounce_pass(const TransferScene& scene, const SampleTable& table, int bands,
                                        std::span<const VertexTransfer> previous, ProgressCounter& progress) {
  return for_each_vertex(scene, bands, progress, [&](const TransferMesh& mesh, size_t v, Scratch& scratch, std::span<glm::dvec3> out) {
    bounce_vertex(scene, table, previous, mesh, v, scratch, out);
  });
}

void accumulate(std::vector<VertexTransfer>& total, const std::vector<VertexTransfer>& bounce) {
  for (size_t m = 0; m < total.size(); ++m)
    for (size_t i = 0; i < total[m].coefficients.size(); ++i) total[m].coefficients[i] += bounce[m].coefficients[i];
}

}  // namespace

std::expected<void, std::string> check_transfer_options(const TransferOptions& options) { return check(options, true); }

std::expected<std::vector<VertexTransfer>, std::string> compute_transfer(const TransferScene& scene, const TransferOptions& options,
                                                                         const TransferProgress& progress) {
  if (auto valid = check(options, true); !valid) return std::unexpected(valid.error());
  const std::vector<Sample> samples = jittered_samples(options.grid, options.seed);
  return compute_transfer(scene, options, samples, progress);
}

std::expected<std::vector<VertexTransfer>, std::string> compute_transfer(const TransferScene& scene, const TransferOptions& options,
                                                                         std::span<const Sample> samples,
                                                                         const TransferProgress& progress) {
  if (auto valid = check(options, false); !valid) return std::unexpected(valid.error());
  auto table = make_table(samples, options.bands);
  if (!table) return std::unexpected(table.error());
  const int bounces = options.kind == TransferKind::interreflected ? options.bounces : 0;
  ProgressCounter counter(progress, scene.vertex_count() * static_cast<size_t>(1 + bounces));

  std::vector<VertexTransfer> total =
      direct_pass(scene, *table, options.bands, options.kind != TransferKind::unshadowed, counter);
  // Each bounce gathers the previous bounce alone (not the running sum), so no light is
  // counted twice; the result is the direct term plus every bounce (book step 7).
  std::vector<VertexTransfer> last = total;
  for (int b = 0; b < bounces; ++b) {
    last = bounce_pass(scene, *table, options.bands, last, counter);
    accumulate(total, last);
  }
  return total;
}

std::expected<std::vector<VertexTransfer>, std::string> transfer_bounce(const TransferScene& scene,
                                                                        std::span<const VertexTransfer> previous,
                                                                        std::span<const Sample> samples,
                                                                        const TransferProgress& progress) {
  if (previous.size() != scene.meshes().size())
    return std::unexpected(fmt::format("transfer bounce: {} transfers for {} meshes", previous.size(), scene.meshes().size()));
  const int bands = previous.empty() ? 1 : previous.front().bands;
  if (bands < 1 || bands > max_bands) return std::unexpected(fmt::format("transfer bounce: bands {} outside [1, {}]", bands, max_bands));
  for (size_t m = 0; m < previous.size(); ++m) {
    const size_t expected = scene.meshes()[m].positions.size() * static_cast<size_t>(coefficient_count(bands));
    if (previous[m].bands != bands || previous[m].coefficients.size() != expected)
      return std::unexpected(fmt::format("transfer bounce: mesh {} has {} coefficients at {} bands, expected {} at {}", m,
                                         previous[m].coefficients.size(), previous[m].bands, expected, bands));
  }
  auto table = make_table(samples, bands);
  if (!table) return std::unexpected(table.error());
  ProgressCounter counter(progress, scene.vertex_count());
  return bounce_pass(scene, *table, bands, previous, counter);
}

glm::dvec3 shade(const VertexTransfer& transfer, size_t vertex, std::span<const glm::dvec3> light) {
  const std::span<const glm::dvec3> t = transfer.vertex(vertex);
  glm::dvec3 sum(0.0);
  for (size_t i = 0; i < std::min(t.size(), light.size()); ++i) sum += t[i] * light[i];
  return sum;
}

glm::dvec3 exact_diffuse_radiance(const TransferScene& scene, const glm::dvec3& point, const glm::dvec3& normal,
                                  const glm::dvec3& albedo, const RadianceFunction& radiance,
                                  const std::vector<Sample>& quadrature, bool shadowed) {
  const glm::dvec3 n = glm::normalize(normal);
  std::vector<size_t> active;
  std::vector<double> cosines;
  std::vector<glm::dvec3> directions;
  std::vector<glm::vec3> ray_directions;
  for (size_t s = 0; s < quadrature.size(); ++s) {
    // Quadrature directions are in the SH frame (Sampling.h), the point and normal are not.
    const glm::dvec3 d = from_sh_frame(glm::normalize(quadrature[s].direction));
    const double c = glm::dot(n, d);
    if (c > 0.0) {
      active.push_back(s);
      cosines.push_back(c);
      directions.push_back(d);
      ray_directions.emplace_back(d);
    }
  }
  std::vector<uint8_t> blocked(active.size(), 0);
  if (shadowed) scene.occluded(scene.ray_origin(point, n), ray_directions, blocked);
  glm::dvec3 sum(0.0);
  for (size_t k = 0; k < active.size(); ++k)
    if (!blocked[k])
      sum += quadrature[active[k]].weight * cosines[k] * radiance(directions[k]);
  return albedo * std::numbers::inv_pi * sum;
}

glm::dvec3 exact_directional(const TransferScene& scene, const glm::dvec3& point, const glm::dvec3& normal,
                             const glm::dvec3& albedo, const glm::dvec3& light_direction, const glm::dvec3& intensity,
                             bool shadowed) {
  const glm::dvec3 n = glm::normalize(normal);
  const glm::dvec3 l = glm::normalize(light_direction);
  const double c = glm::dot(n, l);
  if (c <= 0.0) return glm::dvec3(0.0);
  if (shadowed && scene.occluded(scene.ray_origin(point, n), l)) return glm::dvec3(0.0);
  return albedo * std::numbers::inv_pi * intensity * c;
}

}  // namespace sh
