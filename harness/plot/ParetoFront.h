#pragma once
// The Pareto front of (cost, error) points, both minimised: the points no other point
// beats on one axis without losing on the other. A sweep reports it so the variants
// worth using stand out from the ones that are slower *and* less accurate.
#include <cstddef>
#include <span>
#include <vector>

namespace shaderbed {

struct CostError {
  double cost = 0;
  double error = 0;
};

struct ParetoFront {
  // Indices into the input of the points on the front, by cost, then error, then
  // input order. Exact duplicates do not dominate each other: both are on the front.
  std::vector<std::size_t> front;
  // Indices of points whose cost or error is NaN or infinite. They are never on the
  // front (nor do they dominate anything) but are kept so a chart can still show them.
  std::vector<std::size_t> non_finite;
};

// Point a dominates b when a.cost <= b.cost and a.error <= b.error, one strictly.
bool dominates(const CostError& a, const CostError& b);

ParetoFront find_pareto_front(std::span<const CostError> points);

}  // namespace shaderbed
