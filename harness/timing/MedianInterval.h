#pragma once
// The median of repeated timings and a distribution-free confidence interval for it
// from order statistics (the binomial method): timings are skewed and heavy-tailed, so a
// mean ± t·s interval would be wrong. With n samples the interval [x(j), x(n+1-j)] covers
// the true median with probability 1 - 2 P(B <= j-1), B ~ Binomial(n, 1/2); j is the
// largest rank that keeps that at or above the requested level. Below n = 6 no rank
// reaches 95 %: the interval is then [min, max] and `level` says what it does cover.
#include <vector>

namespace shaderbed {

struct MedianInterval {
  double median = 0;
  double low = 0;
  double high = 0;
  double level = 0;   // the interval's actual coverage probability, e.g. 0.96
  int samples = 0;
};

// An empty input gives samples = 0 and zeros.
MedianInterval median_interval(std::vector<double> samples, double wanted_level = 0.95);

}  // namespace shaderbed
