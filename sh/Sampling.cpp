// Sphere sample sets (Sampling.h): the book's jittered grid and a Gauss-Legendre product rule.
#include "sh/Sampling.h"

#include <cmath>
#include <numbers>
#include <random>
#include <utility>

#include "sh/Basis.h"

namespace sh {

namespace {

constexpr double pi = std::numbers::pi;

glm::dvec3 spherical_direction(double cos_theta, double phi) {
  const double sin_theta = std::sqrt(std::max(0.0, (1.0 - cos_theta) * (1.0 + cos_theta)));
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

}  // namespace

std::vector<Sample> jittered_samples(int grid, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  // The top 53 bits as a multiple of 2^-53: uniform on [0, 1), the same on every platform.
  auto uniform = [&engine] { return double(engine() >> 11) * 0x1.0p-53; };
  std::vector<Sample> samples;
  if (grid <= 0) return samples;
  samples.reserve(std::size_t(grid) * grid);
  const double weight = 4.0 * pi / (double(grid) * grid);
  for (int a = 0; a < grid; ++a) {
    for (int b = 0; b < grid; ++b) {
      const double x = (a + uniform()) / grid;
      const double y = (b + uniform()) / grid;
      const double theta = 2.0 * std::acos(std::sqrt(1.0 - x));
      const double phi = 2.0 * pi * y;
      samples.push_back({{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)}, weight});
    }
  }
  return samples;
}

GaussLegendre gauss_legendre(int n) {
  GaussLegendre rule;
  if (n <= 0) return rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  // P_n'(x) from (x^2 - 1) P_n' = n (x P_n - P_{n-1}), with P_n by the three-term recurrence.
  auto value_and_derivative = [n](double x) {
    double previous = 1.0, current = x;
    for (int j = 2; j <= n; ++j) {
      const double next = ((2.0 * j - 1.0) * x * current - (j - 1.0) * previous) / j;
      previous = current;
      current = next;
    }
    return std::pair{current, n * (x * current - previous) / (x * x - 1.0)};
  };
  for (int k = 0; k < n; ++k) {
    // Tricomi's estimate of the k-th root from the top, then Newton.
    double x = std::cos(pi * (k + 0.75) / (n + 0.5));
    for (int iteration = 0; iteration < 100; ++iteration) {
      const auto [p, dp] = value_and_derivative(x);
      const double step = p / dp;
      x -= step;
      if (std::abs(step) < 1e-12) break;  // quadratic convergence: the error left is ~step^2
    }
    const double dp = value_and_derivative(x).second;
    rule.nodes[n - 1 - k] = x;
    rule.weights[n - 1 - k] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  return rule;
}

std::vector<Sample> gauss_legendre_samples(int n_theta, int n_phi) {
  std::vector<Sample> samples;
  if (n_theta <= 0 || n_phi <= 0) return samples;
  const GaussLegendre rule = gauss_legendre(n_theta);
  samples.reserve(std::size_t(n_theta) * n_phi);
  const double step = 2.0 * pi / n_phi;
  for (int k = 0; k < n_theta; ++k)
    for (int j = 0; j < n_phi; ++j)
      samples.push_back({spherical_direction(rule.nodes[k], (j + 0.5) * step), rule.weights[k] * step});
  return samples;
}

SampleSet::SampleSet(std::vector<Sample> samples, int bands)
    : samples_(std::move(samples)), bands_(std::max(bands, 0)) {
  const std::size_t n = std::size_t(bands_) * bands_;
  basis_.resize(samples_.size() * n);
  for (std::size_t s = 0; s < samples_.size(); ++s)
    basis_all(bands_, samples_[s].direction, std::span<double>(basis_).subspan(s * n, n));
}

}  // namespace sh
