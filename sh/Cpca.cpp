#include "sh/Cpca.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace sh {

namespace {

// splitmix64: a fixed, portable sequence (std::uniform_real_distribution is not specified
// bit for bit, and the clustering must not change between standard libraries).
class Random {
 public:
  explicit Random(uint64_t seed) : state_(seed) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1p-53; }  // [0, 1)

 private:
  uint64_t state_;
};

// Eigen-decomposition of a symmetric n×n matrix (row-major) by cyclic Jacobi rotations:
// slow (O(n³) a sweep) but simple and accurate to rounding, and n is at most a few
// hundred here. Returns the eigenvalues descending and the eigenvectors as rows.
struct Eigen {
  std::vector<double> values;
  std::vector<double> vectors;  // row i is the eigenvector of values[i]
};

Eigen symmetric_eigen(std::vector<double> a, size_t n) {
  std::vector<double> v(n * n, 0.0);
  for (size_t i = 0; i < n; ++i) v[i * n + i] = 1.0;
  const double total = std::inner_product(a.begin(), a.end(), a.begin(), 0.0);
  for (int sweep = 0; sweep < 100 && total > 0.0; ++sweep) {
    double off = 0.0;
    for (size_t p = 0; p < n; ++p)
      for (size_t q = p + 1; q < n; ++q) off += a[p * n + q] * a[p * n + q];
    if (off <= 1e-32 * total) break;  // off-diagonal mass far below the rounding of the diagonal
    for (size_t p = 0; p < n; ++p)
      for (size_t q = p + 1; q < n; ++q) {
        const double apq = a[p * n + q];
        if (apq == 0.0) continue;
        // The rotation that zeroes a_pq: t = tan φ, the smaller root of t² + 2θt − 1 = 0.
        const double theta = (a[q * n + q] - a[p * n + p]) / (2.0 * apq);
        const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (size_t k = 0; k < n; ++k) {  // A ← A·J
          const double akp = a[k * n + p], akq = a[k * n + q];
          a[k * n + p] = c * akp - s * akq;
          a[k * n + q] = s * akp + c * akq;
        }
        for (size_t k = 0; k < n; ++k) {  // A ← Jᵀ·A
          const double apk = a[p * n + k], aqk = a[q * n + k];
          a[p * n + k] = c * apk - s * aqk;
          a[q * n + k] = s * apk + c * aqk;
        }
        a[p * n + q] = a[q * n + p] = 0.0;
        for (size_t k = 0; k < n; ++k) {  // V ← V·J: the columns are the eigenvectors
          const double vkp = v[k * n + p], vkq = v[k * n + q];
          v[k * n + p] = c * vkp - s * vkq;
          v[k * n + q] = s * vkp + c * vkq;
        }
      }
  }
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t i, size_t j) { return a[i * n + i] > a[j * n + j]; });
  Eigen result;
  result.vectors.resize(n * n);
  for (size_t r = 0; r < n; ++r) {
    result.values.push_back(a[order[r] * n + order[r]]);
    for (size_t k = 0; k < n; ++k) result.vectors[r * n + k] = v[k * n + order[r]];
  }
  return result;
}

// The data, the current partition, and each cluster's mean and basis.
struct State {
  std::span<const double> data;
  size_t count = 0, dimension = 0, clusters = 0, vectors = 0;
  std::vector<int> assignment;
  std::vector<double> means;  // clusters × dimension
  std::vector<double> basis;  // clusters × vectors × dimension

  const double* row(size_t v) const { return data.data() + v * dimension; }
  double* mean(size_t k) { return means.data() + k * dimension; }
  const double* mean(size_t k) const { return means.data() + k * dimension; }
  double* basis_vector(size_t k, size_t j) { return basis.data() + (k * vectors + j) * dimension; }
  const double* basis_vector(size_t k, size_t j) const { return basis.data() + (k * vectors + j) * dimension; }

  double squared_distance(size_t v, const double* to) const {
    const double* x = row(v);
    double sum = 0.0;
    for (size_t d = 0; d < dimension; ++d) sum += (x[d] - to[d]) * (x[d] - to[d]);
    return sum;
  }
  // |x − M_k|² minus the part the orthonormal basis captures: the reconstruction error.
  double reconstruction_error(size_t v, size_t k, std::vector<double>& centred) const {
    const double* x = row(v);
    const double* m = mean(k);
    double error = 0.0;
    for (size_t d = 0; d < dimension; ++d) {
      centred[d] = x[d] - m[d];
      error += centred[d] * centred[d];
    }
    for (size_t j = 0; j < vectors; ++j) {
      const double* b = basis_vector(k, j);
      double w = 0.0;
      for (size_t d = 0; d < dimension; ++d) w += centred[d] * b[d];
      error -= w * w;
    }
    return std::max(error, 0.0);
  }
  std::vector<std::vector<size_t>> members() const {
    std::vector<std::vector<size_t>> out(clusters);
    for (size_t v = 0; v < count; ++v) out[static_cast<size_t>(assignment[v])].push_back(v);
    return out;
  }
};

// k-means++: the first centre uniformly, each next one with probability ∝ the squared
// distance to the nearest centre so far.
void seed_means(State& s, Random& random) {
  std::vector<double> nearest(s.count, std::numeric_limits<double>::infinity());
  size_t pick = static_cast<size_t>(random.uniform() * static_cast<double>(s.count));
  for (size_t k = 0; k < s.clusters; ++k) {
    std::copy_n(s.row(pick), s.dimension, s.mean(k));
    double total = 0.0;
    for (size_t v = 0; v < s.count; ++v) {
      nearest[v] = std::min(nearest[v], s.squared_distance(v, s.mean(k)));
      total += nearest[v];
    }
    if (total <= 0.0) {  // every point is already a centre: any will do
      pick = static_cast<size_t>(random.uniform() * static_cast<double>(s.count));
      continue;
    }
    double target = random.uniform() * total;
    pick = s.count - 1;
    for (size_t v = 0; v < s.count; ++v) {
      target -= nearest[v];
      if (target < 0.0 && nearest[v] > 0.0) {
        pick = v;
        break;
      }
    }
  }
}

// Gives every empty cluster the vertex worst served by its own cluster, so k stays k.
void refill_empty(State& s, const std::vector<double>& error) {
  std::vector<size_t> sizes(s.clusters, 0);
  for (int k : s.assignment) ++sizes[static_cast<size_t>(k)];
  std::vector<size_t> by_error(s.count);
  std::iota(by_error.begin(), by_error.end(), size_t{0});
  std::stable_sort(by_error.begin(), by_error.end(), [&](size_t a, size_t b) { return error[a] > error[b]; });
  size_t next = 0;
  for (size_t k = 0; k < s.clusters; ++k) {
    while (sizes[k] == 0 && next < by_error.size()) {
      const size_t v = by_error[next++];
      const auto from = static_cast<size_t>(s.assignment[v]);
      if (sizes[from] <= 1) continue;  // would empty another cluster
      --sizes[from];
      s.assignment[v] = static_cast<int>(k);
      ++sizes[k];
    }
  }
}

void update_means(State& s, const std::vector<std::vector<size_t>>& members) {
  for (size_t k = 0; k < s.clusters; ++k) {
    if (members[k].empty()) continue;
    double* m = s.mean(k);
    std::fill_n(m, s.dimension, 0.0);
    for (size_t v : members[k])
      for (size_t d = 0; d < s.dimension; ++d) m[d] += s.row(v)[d];
    for (size_t d = 0; d < s.dimension; ++d) m[d] /= static_cast<double>(members[k].size());
  }
}

// Cluster k's mean and top principal directions. With fewer members than dimensions the
// m×m Gram matrix Y·Yᵀ is decomposed instead of the D×D covariance Yᵀ·Y (same non-zero
// spectrum, b = Yᵀu/√λ), which keeps many small clusters cheap.
void cluster_pca(State& s, size_t k, const std::vector<size_t>& members) {
  const size_t d_count = s.dimension, m_count = members.size();
  std::fill_n(s.basis_vector(k, 0), s.vectors * d_count, 0.0);
  if (m_count == 0 || s.vectors == 0) return;
  const double* m = s.mean(k);
  std::vector<double> y(m_count * d_count);  // centred members, row-major
  for (size_t i = 0; i < m_count; ++i)
    for (size_t d = 0; d < d_count; ++d) y[i * d_count + d] = s.row(members[i])[d] - m[d];

  if (m_count < d_count) {
    std::vector<double> gram(m_count * m_count);
    for (size_t i = 0; i < m_count; ++i)
      for (size_t j = i; j < m_count; ++j) {
        double sum = 0.0;
        for (size_t d = 0; d < d_count; ++d) sum += y[i * d_count + d] * y[j * d_count + d];
        gram[i * m_count + j] = gram[j * m_count + i] = sum;
      }
    const Eigen eigen = symmetric_eigen(std::move(gram), m_count);
    const double floor = 1e-24 * std::max(eigen.values.empty() ? 0.0 : eigen.values.front(), 0.0);
    size_t filled = 0;
    for (size_t r = 0; r < m_count && filled < s.vectors; ++r) {
      if (!(eigen.values[r] > floor)) break;
      double* b = s.basis_vector(k, filled);
      for (size_t i = 0; i < m_count; ++i)
        for (size_t d = 0; d < d_count; ++d) b[d] += eigen.vectors[r * m_count + i] * y[i * d_count + d];
      // Re-orthonormalise against the earlier vectors: small eigenvalues lose orthogonality.
      for (size_t j = 0; j < filled; ++j) {
        const double* previous = s.basis_vector(k, j);
        const double dot = std::inner_product(b, b + d_count, previous, 0.0);
        for (size_t d = 0; d < d_count; ++d) b[d] -= dot * previous[d];
      }
      const double length = std::sqrt(std::inner_product(b, b + d_count, b, 0.0));
      if (length <= 1e-9 * std::sqrt(eigen.values[r])) {
        std::fill_n(b, d_count, 0.0);
        break;
      }
      for (size_t d = 0; d < d_count; ++d) b[d] /= length;
      ++filled;
    }
    return;
  }
  std::vector<double> covariance(d_count * d_count, 0.0);
  for (size_t i = 0; i < m_count; ++i) {
    const double* row = &y[i * d_count];
    for (size_t a = 0; a < d_count; ++a)
      for (size_t b = a; b < d_count; ++b) covariance[a * d_count + b] += row[a] * row[b];
  }
  for (size_t a = 0; a < d_count; ++a)
    for (size_t b = 0; b < a; ++b) covariance[a * d_count + b] = covariance[b * d_count + a];
  const Eigen eigen = symmetric_eigen(std::move(covariance), d_count);
  for (size_t j = 0; j < s.vectors; ++j) std::copy_n(&eigen.vectors[j * d_count], d_count, s.basis_vector(k, j));
}

void all_pca(State& s, const std::vector<std::vector<size_t>>& members) {
  tbb::parallel_for(size_t{0}, s.clusters, [&](size_t k) { cluster_pca(s, k, members[k]); });
}

// Moves every vertex to its best cluster under `error(v, k)`; returns whether any moved,
// and each vertex's error there.
template <typename Error>
bool assign(State& s, std::vector<double>& best_error, const Error& error) {
  std::vector<uint8_t> moved(s.count, 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, s.count, 64), [&](const tbb::blocked_range<size_t>& range) {
    std::vector<double> centred(s.dimension);
    for (size_t v = range.begin(); v != range.end(); ++v) {
      int best = 0;
      double lowest = std::numeric_limits<double>::infinity();
      for (size_t k = 0; k < s.clusters; ++k) {
        const double e = error(v, k, centred);
        if (e < lowest) {  // ties keep the lower index: deterministic
          lowest = e;
          best = static_cast<int>(k);
        }
      }
      moved[v] = s.assignment[v] != best;
      s.assignment[v] = best;
      best_error[v] = lowest;
    }
  });
  return std::find(moved.begin(), moved.end(), uint8_t{1}) != moved.end();
}

}  // namespace

std::vector<double> CpcaResult::reconstruct(size_t vertex) const {
  const auto d_count = static_cast<size_t>(dimension), n = static_cast<size_t>(pca_vectors);
  const auto k = static_cast<size_t>(cluster_of_vertex[vertex]);
  std::vector<double> x(means.begin() + static_cast<std::ptrdiff_t>(k * d_count),
                        means.begin() + static_cast<std::ptrdiff_t>((k + 1) * d_count));
  for (size_t j = 0; j < n; ++j) {
    const double w = weights[vertex * n + j];
    const double* b = &basis[(k * n + j) * d_count];
    for (size_t d = 0; d < d_count; ++d) x[d] += w * b[d];
  }
  return x;
}

std::expected<CpcaResult, std::string> cpca(std::span<const double> vectors, int dimension, const CpcaOptions& options) {
  if (dimension < 1) return std::unexpected(fmt::format("cpca: dimension {} must be positive", dimension));
  const auto d_count = static_cast<size_t>(dimension);
  if (vectors.empty() || vectors.size() % d_count != 0)
    return std::unexpected(fmt::format("cpca: {} values are not a whole number of {}-vectors", vectors.size(), dimension));
  const size_t count = vectors.size() / d_count;
  if (options.clusters < 1 || static_cast<size_t>(options.clusters) > count)
    return std::unexpected(fmt::format("cpca: {} clusters for {} vertices", options.clusters, count));
  if (options.pca_vectors < 0 || options.pca_vectors > dimension)
    return std::unexpected(fmt::format("cpca: {} PCA vectors outside [0, {}]", options.pca_vectors, dimension));
  if (options.iterations < 0) return std::unexpected(fmt::format("cpca: {} iterations", options.iterations));
  for (size_t i = 0; i < vectors.size(); ++i)
    if (!std::isfinite(vectors[i])) return std::unexpected(fmt::format("cpca: vertex {} has a non-finite value", i / d_count));

  State s;
  s.data = vectors;
  s.count = count;
  s.dimension = d_count;
  s.clusters = static_cast<size_t>(options.clusters);
  s.vectors = static_cast<size_t>(options.pca_vectors);
  s.assignment.assign(count, -1);
  s.means.assign(s.clusters * d_count, 0.0);
  s.basis.assign(s.clusters * s.vectors * d_count, 0.0);
  std::vector<double> error(count, 0.0);

  Random random(options.seed);
  seed_means(s, random);
  const auto to_mean = [&](size_t v, size_t k, std::vector<double>&) { return s.squared_distance(v, s.mean(k)); };
  assign(s, error, to_mean);
  refill_empty(s, error);
  for (int i = 0; i < options.iterations; ++i) {
    update_means(s, s.members());
    const bool moved = assign(s, error, to_mean);
    refill_empty(s, error);
    if (!moved) break;
  }
  auto members = s.members();
  update_means(s, members);
  all_pca(s, members);
  // CPCA rounds: with no PCA vectors the error is the distance to the mean, which Lloyd
  // has already minimised.
  for (int i = 0; i < options.iterations && s.vectors > 0; ++i) {
    const bool moved = assign(s, error, [&](size_t v, size_t k, std::vector<double>& centred) {
      return s.reconstruction_error(v, k, centred);
    });
    refill_empty(s, error);
    members = s.members();
    update_means(s, members);
    all_pca(s, members);
    if (!moved) break;
  }

  CpcaResult result;
  result.clusters = options.clusters;
  result.pca_vectors = options.pca_vectors;
  result.dimension = dimension;
  result.cluster_of_vertex = s.assignment;
  result.means = std::move(s.means);
  result.basis = std::move(s.basis);
  result.weights.assign(count * s.vectors, 0.0);
  double squared = 0.0;
  for (size_t v = 0; v < count; ++v) {
    const auto k = static_cast<size_t>(result.cluster_of_vertex[v]);
    const double* x = vectors.data() + v * d_count;
    const double* m = &result.means[k * d_count];
    for (size_t j = 0; j < s.vectors; ++j) {
      const double* b = &result.basis[(k * s.vectors + j) * d_count];
      double w = 0.0;
      for (size_t d = 0; d < d_count; ++d) w += (x[d] - m[d]) * b[d];
      result.weights[v * s.vectors + j] = w;
    }
    const std::vector<double> r = result.reconstruct(v);
    for (size_t d = 0; d < d_count; ++d) squared += (x[d] - r[d]) * (x[d] - r[d]);
  }
  result.rms_error = std::sqrt(squared / static_cast<double>(count));
  return result;
}

std::expected<CpcaResult, std::string> cpca(std::span<const float> vectors, int dimension, const CpcaOptions& options) {
  const std::vector<double> widened(vectors.begin(), vectors.end());
  return cpca(std::span<const double>(widened), dimension, options);
}

std::vector<double> cpca_input(const VertexTransfer& transfer) {
  const auto n = static_cast<size_t>(transfer.bands * transfer.bands);
  const size_t count = transfer.vertex_count();
  std::vector<double> out(count * 3 * n);
  for (size_t v = 0; v < count; ++v)
    for (size_t c = 0; c < 3; ++c)
      for (size_t i = 0; i < n; ++i) out[(v * 3 + c) * n + i] = transfer.coefficients[v * n + i][static_cast<int>(c)];
  return out;
}

std::expected<std::vector<double>, std::string> cluster_light_constants(const CpcaResult& result,
                                                                        std::span<const glm::dvec3> light) {
  const size_t n = light.size();
  if (n == 0 || static_cast<size_t>(result.dimension) != 3 * n)
    return std::unexpected(fmt::format("cluster constants: dimension {} is not 3 × {} light coefficients", result.dimension, n));
  const auto vectors = static_cast<size_t>(result.pca_vectors);
  const auto d_count = static_cast<size_t>(result.dimension);
  const size_t padded = 4 * static_cast<size_t>((result.pca_vectors + 3) / 4);
  const size_t stride = 4 * static_cast<size_t>(cluster_registers(result.pca_vectors));
  std::vector<double> out(static_cast<size_t>(result.clusters) * stride, 0.0);
  // One colour block of a D-vector dotted with that channel of the light.
  const auto dot = [&](const double* vector, size_t channel) {
    double sum = 0.0;
    for (size_t i = 0; i < n; ++i) sum += vector[channel * n + i] * light[i][static_cast<int>(channel)];
    return sum;
  };
  for (size_t k = 0; k < static_cast<size_t>(result.clusters); ++k) {
    double* cluster = &out[k * stride];
    for (size_t c = 0; c < 3; ++c) cluster[c] = dot(&result.means[k * d_count], c);
    for (size_t j = 0; j < vectors; ++j)
      for (size_t c = 0; c < 3; ++c) cluster[4 + c * padded + j] = dot(&result.basis[(k * vectors + j) * d_count], c);
  }
  return out;
}

std::expected<std::vector<float>, std::string> cluster_light_constants_f(const CpcaResult& result,
                                                                         std::span<const glm::dvec3> light) {
  auto constants = cluster_light_constants(result, light);
  if (!constants) return std::unexpected(constants.error());
  return std::vector<float>(constants->begin(), constants->end());
}

glm::dvec3 shade_from_constants(const CpcaResult& result, std::span<const double> constants, size_t vertex) {
  const auto vectors = static_cast<size_t>(result.pca_vectors);
  const size_t padded = 4 * static_cast<size_t>((result.pca_vectors + 3) / 4);
  const size_t stride = 4 * static_cast<size_t>(cluster_registers(result.pca_vectors));
  const double* cluster = &constants[static_cast<size_t>(result.cluster_of_vertex[vertex]) * stride];
  glm::dvec3 colour(cluster[0], cluster[1], cluster[2]);
  for (size_t j = 0; j < vectors; ++j) {
    const double w = result.weights[vertex * vectors + j];
    for (int c = 0; c < 3; ++c) colour[c] += w * cluster[4 + static_cast<size_t>(c) * padded + j];
  }
  return colour;
}

}  // namespace sh
