#include "plot/ParetoFront.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace shaderbed {

namespace {

double low(const CostError& p) { return std::isnan(p.cost_low) ? p.cost : p.cost_low; }
double high(const CostError& p) { return std::isnan(p.cost_high) ? p.cost : p.cost_high; }

bool is_finite(const CostError& p) {
  return std::isfinite(p.cost) && std::isfinite(p.error) && std::isfinite(low(p)) && std::isfinite(high(p));
}

}  // namespace

bool dominates(const CostError& a, const CostError& b) {
  return a.error <= b.error && high(a) <= low(b) && (a.error < b.error || high(a) < low(b));
}

ParetoFront find_pareto_front(std::span<const CostError> points) {
  ParetoFront result;
  std::vector<std::size_t> finite;
  for (std::size_t i = 0; i < points.size(); ++i) (is_finite(points[i]) ? finite : result.non_finite).push_back(i);
  std::sort(finite.begin(), finite.end(), [&](std::size_t a, std::size_t b) {
    return std::tuple(points[a].cost, points[a].error, a) < std::tuple(points[b].cost, points[b].error, b);
  });
  // Each point against every other: with intervals the cheapest-so-far sweep no longer
  // holds (a point's rival may sit on either side of its median), and a scene's points
  // number in the thousands at most.
  for (std::size_t i : finite) {
    bool dominated = false;
    for (std::size_t j : finite) dominated = dominated || (j != i && dominates(points[j], points[i]));
    if (!dominated) result.front.push_back(i);
  }
  return result;
}

}  // namespace shaderbed
