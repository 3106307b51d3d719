// CPCA (book Eq. 9.1): the error falls with more PCA vectors and clusters, a full basis
// reconstructs exactly, and the per-cluster constants shade every vertex as the
// uncompressed reconstruction does.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sh/Cpca.h"

namespace sh {
namespace {

// Shadowed transfer of a small ball on a floor: realistic, smoothly varying data.
std::vector<double> transfer_data(int bands, size_t* vertices) {
  TransferMesh ball;
  ball.albedo = glm::dvec3(0.9, 0.7, 0.4);
  const int stacks = 8, slices = 16;
  for (int j = 0; j <= stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      const double theta = std::numbers::pi * j / stacks, phi = 2.0 * std::numbers::pi * i / slices;
      const glm::dvec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      ball.positions.push_back(0.5 * n + glm::dvec3(0.0, 0.52, 0.0));
      ball.normals.push_back(n);
    }
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      const auto at = [&](int jj, int ii) { return static_cast<uint32_t>(jj * slices + ii % slices); };
      ball.indices.insert(ball.indices.end(), {at(j, i), at(j, i + 1), at(j + 1, i), at(j + 1, i), at(j, i + 1), at(j + 1, i + 1)});
    }
  auto scene = TransferScene::create({ball, ground_plane(0.0, 2.0, 10, glm::dvec3(0.6, 0.6, 0.8))});
  EXPECT_TRUE(scene) << (scene ? "" : scene.error());
  const auto t = compute_transfer(*scene, {.kind = TransferKind::shadowed, .bands = bands, .grid = 8, .seed = 1});
  EXPECT_TRUE(t) << (t ? "" : t.error());
  std::vector<double> data;
  *vertices = 0;
  for (const VertexTransfer& mesh : *t) {
    const std::vector<double> part = cpca_input(mesh);
    data.insert(data.end(), part.begin(), part.end());
    *vertices += mesh.vertex_count();
  }
  return data;
}

CpcaResult run(std::span<const double> data, int dimension, int clusters, int vectors) {
  auto result = cpca(data, dimension, {.clusters = clusters, .pca_vectors = vectors});
  EXPECT_TRUE(result) << (result ? "" : result.error());
  return std::move(*result);
}

TEST(Cpca, ErrorFallsWithMorePcaVectorsAndClusters) {
  size_t count = 0;
  const std::vector<double> data = transfer_data(3, &count);
  const int d = 27;
  double previous = std::numeric_limits<double>::infinity();
  for (int vectors : {0, 1, 2, 4, 8}) {
    const CpcaResult r = run(data, d, 4, vectors);
    EXPECT_LT(r.rms_error, previous) << vectors << " PCA vectors";
    previous = r.rms_error;
  }
  previous = std::numeric_limits<double>::infinity();
  for (int clusters : {1, 2, 4, 16}) {
    const CpcaResult r = run(data, d, clusters, 2);
    EXPECT_LT(r.rms_error, previous) << clusters << " clusters";
    previous = r.rms_error;
  }
  // The reported error is the one the reconstruction has.
  const CpcaResult r = run(data, d, 3, 2);
  double squared = 0.0;
  for (size_t v = 0; v < count; ++v) {
    const std::vector<double> x = r.reconstruct(v);
    for (int i = 0; i < d; ++i) squared += (x[i] - data[v * d + i]) * (x[i] - data[v * d + i]);
  }
  EXPECT_NEAR(r.rms_error, std::sqrt(squared / count), 1e-12);
}

TEST(Cpca, FullBasisReconstructsExactly) {
  // Fewer vertices than dimensions: the centred data spans at most D − 1 directions.
  size_t count = 0;
  const std::vector<double> all = transfer_data(3, &count);
  const int d = 27;
  const std::span<const double> few(all.data(), 20 * d);
  EXPECT_LT(run(few, d, 1, d - 1).rms_error, 1e-13);

  // Many vertices on a (D−1)-dimensional affine subspace: the covariance path.
  const int small = 6;
  std::vector<double> flat;
  for (int v = 0; v < 200; ++v) {
    double last = 0.3;
    for (int i = 0; i + 1 < small; ++i) {
      const double x = std::sin(1.7 * v + 0.9 * i * i + 0.1 * v * i);
      flat.push_back(x);
      last += (i + 1) * 0.25 * x;  // the last coordinate is an affine function of the rest
    }
    flat.push_back(last);
  }
  EXPECT_LT(run(flat, small, 1, small - 1).rms_error, 1e-12);
  EXPECT_GT(run(flat, small, 1, small - 2).rms_error, 1e-3);
}

TEST(Cpca, ClusterConstantsShadeEveryVertexAsTheReconstruction) {
  size_t count = 0;
  const int bands = 3, n = bands * bands;
  const std::vector<double> data = transfer_data(bands, &count);
  for (int vectors : {3, 4, 6}) {  // with and without register padding
    const CpcaResult r = run(data, 3 * n, 5, vectors);
    std::vector<glm::dvec3> light(n);
    for (int i = 0; i < n; ++i) light[i] = glm::dvec3(1.0 + 0.1 * i, std::cos(i), 0.5 - 0.2 * i);
    const auto constants = cluster_light_constants(r, light);
    ASSERT_TRUE(constants) << constants.error();
    EXPECT_EQ(constants->size(), static_cast<size_t>(5 * 4 * cluster_registers(vectors)));
    for (size_t v = 0; v < count; ++v) {
      const std::vector<double> x = r.reconstruct(v);
      glm::dvec3 expected(0.0);
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < n; ++i) expected[c] += x[c * n + i] * light[i][c];
      const glm::dvec3 shaded = shade_from_constants(r, *constants, v);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(shaded[c], expected[c], 1e-12) << "vertex " << v;
    }
    const auto floats = cluster_light_constants_f(r, light);
    ASSERT_TRUE(floats);
    EXPECT_EQ(floats->size(), constants->size());
  }
  EXPECT_FALSE(cluster_light_constants(run(data, 3 * n, 2, 2), std::vector<glm::dvec3>(4)).has_value());
}

TEST(Cpca, DeterministicFloatInputAndErrors) {
  size_t count = 0;
  const std::vector<double> data = transfer_data(2, &count);
  const CpcaResult a = run(data, 12, 6, 3), b = run(data, 12, 6, 3);
  EXPECT_EQ(a.cluster_of_vertex, b.cluster_of_vertex);
  EXPECT_EQ(a.weights, b.weights);
  const std::vector<float> narrow(data.begin(), data.end());
  const auto f = cpca(std::span<const float>(narrow), 12, {.clusters = 6, .pca_vectors = 3});
  ASSERT_TRUE(f) << f.error();
  EXPECT_NEAR(f->rms_error, a.rms_error, 1e-5);
  // Every cluster keeps at least one vertex.
  std::vector<int> sizes(6, 0);
  for (int k : a.cluster_of_vertex) ++sizes[k];
  for (int s : sizes) EXPECT_GT(s, 0);

  EXPECT_FALSE(cpca(std::span<const double>(data), 13, {.clusters = 1}).has_value());
  EXPECT_FALSE(cpca(std::span<const double>(data).first(24), 12, {.clusters = 3}).has_value());
  EXPECT_FALSE(cpca(std::span<const double>(data), 12, {.clusters = 1, .pca_vectors = 13}).has_value());
}

TEST(Cpca, ConstantRegisterBudget) {
  EXPECT_EQ(cluster_registers(24), 19);  // the book's layout
  EXPECT_EQ(cluster_registers(5), 7);    // padded to whole registers per colour
  EXPECT_EQ(max_clusters_for_constant_bytes(24, (256 - 4) * 16), 13);
  EXPECT_EQ(max_clusters_for_constant_bytes(24, 65536), 215);
  EXPECT_EQ(max_clusters_for_constant_bytes(8, 65536), 585);
}

}  // namespace
}  // namespace sh
