#pragma once
// The Pareto front of (cost, error) points, both minimised: the points no other point
// beats on one axis without losing on the other. A sweep reports it so the variants
// worth using stand out from the ones that are slower *and* less accurate. A measured
// cost carries its confidence interval: points whose intervals overlap are not ordered
// by cost (they are within noise), so neither dominates the other.
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

namespace shaderbed {

struct CostError {
  double cost = 0;
  double error = 0;
  // The cost's confidence interval (e.g. the median's); NaN = the cost is exact.
  double cost_low = std::numeric_limits<double>::quiet_NaN();
  double cost_high = std::numeric_limits<double>::quiet_NaN();
};

struct ParetoFront {
  // Indices into the input of the points on the front, by cost, then error, then
  // input order. Exact duplicates do not dominate each other: both are on the front.
  // With intervals, a later front point may have both a higher cost and a higher error
  // than an earlier one: their costs are within noise.
  std::vector<std::size_t> front;
  // Indices of points whose cost or error is NaN or infinite. They are never on the
  // front (nor do they dominate anything) but are kept so a chart can still show them.
  std::vector<std::size_t> non_finite;
};

// Point a dominates b when a.error <= b.error and a's cost interval lies wholly at or
// below b's (a.cost_high <= b.cost_low), one of the two strictly. Exact costs make this
// the plain rule (a.cost <= b.cost, a.error <= b.error, one strictly); overlapping
// intervals never dominate, whatever the errors.
bool dominates(const CostError& a, const CostError& b);

ParetoFront find_pareto_front(std::span<const CostError> points);

}  // namespace shaderbed
