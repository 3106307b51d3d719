#pragma once
// Clustered principal component analysis of per-vertex transfer (Sloan, Hall, Hart and
// Snyder 2003; book §9.1.3, digest §3.3), what D3DXSHPRTCompress did: the vertices' transfer
// vectors are clustered, and each vertex is approximated by its cluster's mean plus a
// weighted sum of the cluster's top principal directions. Shading then needs per cluster
// only the dot products of the mean and of each direction with the light (Eq. 9.1):
//   I = M_k·L + Σ_j w_j (B_kj·L),
// computed on the CPU once per light change (cluster_light_constants), and per vertex a
// cluster index and n weights.
//
// Clustering: k-means++ seeding from a fixed seed, Lloyd iterations, then CPCA rounds that
// move each vertex to the cluster whose mean and basis reconstruct it best and recompute
// each cluster's PCA (each step cannot increase the total error), both bounded.
#include <cstdint>
#include <expected>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "sh/Transfer.h"

namespace sh {

struct CpcaOptions {
  int clusters = 1;
  int pca_vectors = 8;   // per cluster, at most the dimension
  int iterations = 20;   // bound on the Lloyd iterations and on the CPCA rounds, each
  uint64_t seed = 1;     // for the k-means++ seeding
};

struct CpcaResult {
  int clusters = 0, pca_vectors = 0, dimension = 0;
  std::vector<int> cluster_of_vertex;
  std::vector<double> weights;  // vertex-major, pca_vectors each
  std::vector<double> means;    // cluster-major, dimension each
  std::vector<double> basis;    // cluster, vector, dimension: orthonormal, strongest first
                                // (a zero vector where a cluster has too few vertices)
  double rms_error = 0.0;       // √(mean over vertices of |x − reconstruction|²)

  size_t vertex_count() const { return cluster_of_vertex.size(); }
  // Mean of the vertex's cluster plus its weighted basis vectors.
  std::vector<double> reconstruct(size_t vertex) const;
};

// vectors: vertex-major, `dimension` values each.
std::expected<CpcaResult, std::string> cpca(std::span<const double> vectors, int dimension, const CpcaOptions& options);
std::expected<CpcaResult, std::string> cpca(std::span<const float> vectors, int dimension, const CpcaOptions& options);

// A transfer as CPCA input, in the layout of D3DX's cluster bases (digest §3.3 step 5):
// per vertex [R_0 .. R_{n−1}, G_0 .., B_0 ..], n = bands², so D = 3·bands².
std::vector<double> cpca_input(const VertexTransfer& transfer);

// float4 registers per cluster in the SH_VS layout: 1 for (M·L_R, M·L_G, M·L_B, 0), then
// the R, G and B dot products of the PCA vectors, each colour padded to whole registers
// (the book's 1 + 3·(n/4), for n a multiple of 4 as it assumes).
constexpr int cluster_registers(int pca_vectors) { return 1 + 3 * ((pca_vectors + 3) / 4); }

// Per-cluster constants for light coefficients (bands² RGB, SH frame), cluster-major,
// 4·cluster_registers(pca_vectors) values per cluster:
//   [M·L_R, M·L_G, M·L_B, 0, R: B_k0·L_R .. (zero padded), G: .., B: ..].
// The dimension must be 3·light.size() (the cpca_input layout).
std::expected<std::vector<double>, std::string> cluster_light_constants(const CpcaResult& result,
                                                                        std::span<const glm::dvec3> light);
// The same rounded to float, ready to upload as vec4s.
std::expected<std::vector<float>, std::string> cluster_light_constants_f(const CpcaResult& result,
                                                                         std::span<const glm::dvec3> light);

// A vertex shaded from the constants as SH_VS does it (Eq. 9.1).
glm::dvec3 shade_from_constants(const CpcaResult& result, std::span<const double> constants, size_t vertex);

// How many clusters' constants fit in `bytes` (16 bytes a register). The D3D9 limit was
// 256 float4 registers for vs_2_0/3_0, (256 − 4)/19 = 13 clusters at 24 PCA vectors with
// the transform in c0..c3 (digest §3.5 [NOTE]); a uniform block on lavapipe and llvmpipe
// allows 65536 bytes (maxUniformBufferRange, GL_MAX_UNIFORM_BLOCK_SIZE): 215 clusters.
constexpr int max_clusters_for_constant_bytes(int pca_vectors, size_t bytes) {
  return static_cast<int>(bytes / (16 * static_cast<size_t>(cluster_registers(pca_vectors))));
}

}  // namespace sh
