#include "timing/MedianInterval.h"

#include <algorithm>
#include <cmath>

#include <boost/math/distributions/binomial.hpp>

namespace shaderbed {
namespace {

// P(B <= k) for B ~ Binomial(n, 1/2).
double binomial_cdf_half(int n, int k) { return boost::math::cdf(boost::math::binomial(n, 0.5), k); }

}  // namespace

MedianInterval median_interval(std::vector<double> samples, double wanted_level) {
  MedianInterval m;
  const int n = int(samples.size());
  m.samples = n;
  if (n == 0) return m;
  std::sort(samples.begin(), samples.end());
  m.median = n % 2 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
  int j = 1;   // 1-based rank of the lower bound
  while (j + 1 <= n / 2 && 1 - 2 * binomial_cdf_half(n, j) >= wanted_level) ++j;
  m.low = samples[j - 1];
  m.high = samples[n - j];
  m.level = 1 - 2 * binomial_cdf_half(n, j - 1);
  return m;
}

}  // namespace shaderbed
