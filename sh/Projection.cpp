// Projection onto SH and coefficient arithmetic (Projection.h).
#include "sh/Projection.h"

#include <algorithm>
#include <numbers>

#include "sh/Basis.h"

namespace sh {

namespace {

template <typename T, typename F>
std::vector<T> project_with(const F& f, const SampleSet& samples, int bands) {
  const std::size_t n = std::size_t(coefficient_count(std::clamp(bands, 0, samples.bands())));
  std::vector<T> result(n, T(0));
  for (std::size_t s = 0; s < samples.size(); ++s) {
    const Sample& sample = samples.samples()[s];
    const T value = f(sample.direction) * sample.weight;
    const auto y = samples.basis(s);
    for (std::size_t i = 0; i < n; ++i) result[i] += value * y[i];
  }
  return result;
}

template <typename T>
T evaluate_with(std::span<const T> coefficients, const glm::dvec3& direction) {
  const int bands = band_count(coefficients.size());
  std::vector<double> y(std::size_t(coefficient_count(bands)));
  basis_all(bands, direction, y);
  T sum(0);
  for (std::size_t i = 0; i < y.size(); ++i) sum += coefficients[i] * y[i];
  return sum;
}

template <typename T>
std::vector<T> add_with(std::span<const T> a, std::span<const T> b) {
  std::vector<T> sum(std::max(a.size(), b.size()), T(0));
  for (std::size_t i = 0; i < a.size(); ++i) sum[i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i) sum[i] += b[i];
  return sum;
}

template <typename R, typename A, typename B>
R dot_with(std::span<const A> a, std::span<const B> b) {
  R sum(0);
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) sum += a[i] * b[i];
  return sum;
}

}  // namespace

std::vector<double> project(const ScalarFunction& f, const SampleSet& samples) {
  return project_with<double>(f, samples, samples.bands());
}
std::vector<glm::dvec3> project_rgb(const RgbFunction& f, const SampleSet& samples) {
  return project_with<glm::dvec3>(f, samples, samples.bands());
}
std::vector<double> project(const ScalarFunction& f, const SampleSet& samples, int bands) {
  return project_with<double>(f, samples, bands);
}
std::vector<glm::dvec3> project_rgb(const RgbFunction& f, const SampleSet& samples, int bands) {
  return project_with<glm::dvec3>(f, samples, bands);
}

std::vector<double> zonal_moments(int bands, const std::function<double(double)>& g, double t0, int degree) {
  std::vector<double> moments(std::size_t(std::max(bands, 0)), 0.0);
  if (bands <= 0 || t0 >= 1.0) return moments;
  t0 = std::max(t0, -1.0);
  // g P_l has degree <= degree + bands - 1; n nodes integrate degree 2n - 1 exactly.
  const GaussLegendre rule = gauss_legendre((std::max(degree, 0) + bands) / 2 + 1);
  const double half = 0.5 * (1.0 - t0), middle = 0.5 * (1.0 + t0);
  for (std::size_t k = 0; k < rule.nodes.size(); ++k) {
    const double t = middle + half * rule.nodes[k];
    const double w = half * rule.weights[k] * g(t);
    double previous = 0.0, current = 1.0;  // P_{l-1}, P_l
    for (int l = 0; l < bands; ++l) {
      moments[l] += w * current;
      const double next = ((2.0 * l + 1.0) * t * current - l * previous) / (l + 1.0);
      previous = current;
      current = next;
    }
  }
  return moments;
}

std::vector<double> project_zonal(int bands, const glm::dvec3& axis, const std::function<double(double)>& g, double t0,
                                  int degree) {
  // The addition theorem: sum_m y_lm(a) y_lm(w) = (2l+1)/(4 pi) P_l(a . w), so
  // c_lm = integral of g(a . w) y_lm(w) dw = 2 pi G_l y_lm(a).
  const std::vector<double> moments = zonal_moments(bands, g, t0, degree);
  std::vector<double> coefficients(std::size_t(coefficient_count(std::max(bands, 0))));
  basis_all(bands, glm::normalize(axis), coefficients);
  for (int l = 0; l < bands; ++l)
    for (int m = -l; m <= l; ++m) coefficients[index(l, m)] *= 2.0 * std::numbers::pi * moments[l];
  return coefficients;
}

double evaluate(std::span<const double> coefficients, const glm::dvec3& direction) {
  return evaluate_with(coefficients, direction);
}
glm::dvec3 evaluate(std::span<const glm::dvec3> coefficients, const glm::dvec3& direction) {
  return evaluate_with(coefficients, direction);
}

std::vector<double> add(std::span<const double> a, std::span<const double> b) { return add_with(a, b); }
std::vector<glm::dvec3> add(std::span<const glm::dvec3> a, std::span<const glm::dvec3> b) { return add_with(a, b); }

std::vector<double> scale(std::span<const double> a, double s) {
  std::vector<double> result(a.begin(), a.end());
  for (double& c : result) c *= s;
  return result;
}
std::vector<glm::dvec3> scale(std::span<const glm::dvec3> a, const glm::dvec3& s) {
  std::vector<glm::dvec3> result(a.begin(), a.end());
  for (glm::dvec3& c : result) c *= s;
  return result;
}

double dot(std::span<const double> a, std::span<const double> b) { return dot_with<double>(a, b); }
glm::dvec3 dot(std::span<const glm::dvec3> a, std::span<const glm::dvec3> b) { return dot_with<glm::dvec3>(a, b); }
glm::dvec3 dot(std::span<const glm::dvec3> a, std::span<const double> b) { return dot_with<glm::dvec3>(a, b); }

}  // namespace sh
