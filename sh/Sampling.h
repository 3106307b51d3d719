#pragma once
// Sample sets on the unit sphere (SH frame, z up) and their quadrature weights, so that
// sum(weight * f(direction)) approximates the integral of f over the sphere.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace sh {

struct Sample {
  glm::dvec3 direction;  // unit, SH frame
  double weight;         // quadrature weight (steradians)
};

// The seed of the project's jittered sets unless a caller chooses one (the book's year).
inline constexpr std::uint64_t default_seed = 2004;

// The book's jittered stratified grid (Ch. 8, 8.2.2): one uniformly random point in each
// cell of a grid x grid partition of the unit square, mapped by theta = 2 acos(sqrt(1-x)),
// phi = 2 pi y (cos theta = 1 - 2x: uniform on the sphere), each weighted 4 pi / grid^2.
// Cells in the book's order (x major). Reproducible: std::mt19937_64 seeded with `seed`
// and a fixed 53-bit conversion to [0, 1), never a standard-library distribution.
std::vector<Sample> jittered_samples(int grid, std::uint64_t seed = default_seed);

// Gauss-Legendre nodes and weights on [-1, 1], n >= 1, by Newton's method on P_n.
struct GaussLegendre {
  std::vector<double> nodes;  // ascending
  std::vector<double> weights;
};
GaussLegendre gauss_legendre(int n);

// A product rule: n_theta Gauss-Legendre nodes in cos theta times n_phi equally spaced
// azimuths (offset by half a step). It integrates exactly every polynomial in (x, y, z)
// of degree <= min(2 n_theta - 1, n_phi - 1); so the product of two functions of B bands
// needs n_theta >= B and n_phi >= 2B - 1.
std::vector<Sample> gauss_legendre_samples(int n_theta, int n_phi);

// Samples plus every basis value y_i (i < bands^2) at each of them, so that a projection
// is one matrix-vector product. Row s of basis() belongs to samples()[s].
class SampleSet {
 public:
  SampleSet(std::vector<Sample> samples, int bands);

  int bands() const { return bands_; }
  std::size_t size() const { return samples_.size(); }
  std::span<const Sample> samples() const { return samples_; }
  // The bands^2 basis values at sample s.
  std::span<const double> basis(std::size_t s) const {
    const std::size_t n = std::size_t(bands_) * bands_;
    return std::span<const double>(basis_).subspan(s * n, n);
  }

 private:
  std::vector<Sample> samples_;
  int bands_;
  std::vector<double> basis_;  // size() x bands^2, row major
};

}  // namespace sh
