#pragma once
// Per-vertex diffuse transfer (book §8.2.4.2 to 8.2.4.4, digest §2.5): for every vertex,
// the SH coefficients T_i of the function that turns distant lighting L into outgoing
// radiance, L_o = Σ_i T_i·L_i per colour channel. The albedo/π is inside T (as the book
// does), the coefficients are in the SH frame (samples come in the SH frame, z up, as
// Sampling.h makes them; rays go along from_sh_frame of them, in the scene's y-up object
// space, and the basis is evaluated at the sample itself, i.e. at to_sh_frame of the ray),
// and every vertex uses the same sample directions, so the basis is evaluated once per
// sample.
//
//   unshadowed      T = (ρ/π) ∫ max(n·ω, 0) y(ω) dω
//   shadowed        T = (ρ/π) ∫ V(ω) max(n·ω, 0) y(ω) dω
//   interreflected  T = shadowed + Σ_bounces B_k, with
//                   B_k(x) = (ρ_x/π) ∫ (1 − V(ω)) max(n_x·ω, 0) B_{k−1}(hit(x, ω)) dω,
//                   B_0 = shadowed, B_{k−1}(hit) interpolated by the hit's barycentrics.
// The receiving vertex's cosine, not the hit triangle's: docs/errata.md ("Inter-reflected
// transfer") says why. The integrals are sums over the samples with their weights.
#include <cstdint>
#include <expected>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "sh/Sampling.h"
#include "sh/TransferScene.h"

namespace sh {

enum class TransferKind { unshadowed, shadowed, interreflected };

struct TransferOptions {
  TransferKind kind = TransferKind::shadowed;
  int bands = 4;      // bands² coefficients per channel
  int grid = 32;      // N = grid² jittered samples (jittered_samples(grid, seed))
  uint64_t seed = 1;
  int bounces = 0;    // interreflected only; 0 gives the shadowed transfer
};

// Bands in [1, 20], grid in [1, 1000], bounces in [0, 16] (the inter-reflected kind).
std::expected<void, std::string> check_transfer_options(const TransferOptions& options);

// One mesh's transfer: vertex-major, coefficient i of vertex v at v·bands² + i, RGB.
struct VertexTransfer {
  int bands = 0;
  std::vector<glm::dvec3> coefficients;

  size_t vertex_count() const { return bands > 0 ? coefficients.size() / static_cast<size_t>(bands * bands) : 0; }
  std::span<const glm::dvec3> vertex(size_t v) const {
    const size_t n = static_cast<size_t>(bands * bands);
    return std::span<const glm::dvec3>(coefficients).subspan(v * n, n);
  }
};

// Called as vertices finish (from worker threads, one call at a time, done increasing);
// total counts every pass: vertices × (1 + bounces) for the inter-reflected kind.
using TransferProgress = std::function<void(size_t done, size_t total)>;

// The transfer of every vertex of every mesh of the scene (one VertexTransfer per mesh,
// in the scene's order), with jittered_samples(options.grid, options.seed).
std::expected<std::vector<VertexTransfer>, std::string> compute_transfer(const TransferScene& scene,
                                                                         const TransferOptions& options,
                                                                         const TransferProgress& progress = {});
// The same with a given quadrature (e.g. Gauss-Legendre); options.grid and seed unused.
std::expected<std::vector<VertexTransfer>, std::string> compute_transfer(const TransferScene& scene,
                                                                         const TransferOptions& options,
                                                                         std::span<const Sample> samples,
                                                                         const TransferProgress& progress = {});

// One gather step of the inter-reflected transfer: B(x) from `previous` (the last bounce
// alone, per mesh, as compute_transfer returns it), by the formula above. Rays that miss
// or reach the back of a surface bring nothing.
std::expected<std::vector<VertexTransfer>, std::string> transfer_bounce(const TransferScene& scene,
                                                                        std::span<const VertexTransfer> previous,
                                                                        std::span<const Sample> samples,
                                                                        const TransferProgress& progress = {});

// The book's SHLighting without the scale: Σ_i T_i·L_i per channel, light in the SH frame.
glm::dvec3 shade(const VertexTransfer& transfer, size_t vertex, std::span<const glm::dvec3> light);

// The CPU reference's diffuse radiance, not truncated to SH: (ρ/π) ∫ L(ω) V(ω) max(n·ω, 0) dω
// by the given quadrature (V = 1 unless shadowed; quadrature directions in the SH frame,
// as Sampling.h makes them). Point and normal are in the scene's y-up space and `radiance`
// takes a unit scene-frame direction towards the light (evaluate an SH light at
// to_sh_frame of it); rays leave point + ray_epsilon()·n as in the transfer.
using RadianceFunction = std::function<glm::dvec3(const glm::dvec3& direction)>;
glm::dvec3 exact_diffuse_radiance(const TransferScene& scene, const glm::dvec3& point, const glm::dvec3& normal,
                                  const glm::dvec3& albedo, const RadianceFunction& radiance,
                                  const std::vector<Sample>& quadrature, bool shadowed);

// A delta (directional) light: (ρ/π)·intensity·max(n·l, 0)·V(l), l the unit direction
// towards the light, in the scene frame.
glm::dvec3 exact_directional(const TransferScene& scene, const glm::dvec3& point, const glm::dvec3& normal,
                             const glm::dvec3& albedo, const glm::dvec3& light_direction, const glm::dvec3& intensity,
                             bool shadowed);

}  // namespace sh
