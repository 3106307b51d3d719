#include "timing/MedianInterval.h"

#include <algorithm>
#include <cmath>

namespace shaderbed {
namespace {

// P(B <= k) for B ~ Binomial(n, 1/2), summed in log space so large n cannot overflow.
double binomial_cdf_half(int n, int k) {
  double total = 0;
  for (int i = 0; i <= k; ++i)
    total += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) + n * std::log(0.5));
  return std::min(total, 1.0);
}

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
