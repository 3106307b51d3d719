#include "plot/ParetoFront.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace shaderbed {

bool dominates(const CostError& a, const CostError& b) {
  return a.cost <= b.cost && a.error <= b.error && (a.cost < b.cost || a.error < b.error);
}

ParetoFront find_pareto_front(std::span<const CostError> points) {
  ParetoFront result;
  std::vector<std::size_t> finite;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const bool ok = std::isfinite(points[i].cost) && std::isfinite(points[i].error);
    (ok ? finite : result.non_finite).push_back(i);
  }
  std::sort(finite.begin(), finite.end(), [&](std::size_t a, std::size_t b) {
    return std::tuple(points[a].cost, points[a].error, a) < std::tuple(points[b].cost, points[b].error, b);
  });

  // Sweep by increasing cost, one group of equal cost at a time. Within a group only the
  // lowest error can survive; it survives when it beats every error seen at a strictly
  // lower cost (an equal error at a lower cost dominates it).
  double best_error_so_far = std::numeric_limits<double>::infinity();
  for (std::size_t begin = 0; begin < finite.size();) {
    const double cost = points[finite[begin]].cost;
    std::size_t end = begin;
    while (end < finite.size() && points[finite[end]].cost == cost) ++end;
    const double group_best = points[finite[begin]].error;  // sorted: the group's lowest error comes first
    if (group_best < best_error_so_far) {
      for (std::size_t k = begin; k < end && points[finite[k]].error == group_best; ++k) result.front.push_back(finite[k]);
      best_error_so_far = group_best;
    }
    begin = end;
  }
  return result;
}

}  // namespace shaderbed
