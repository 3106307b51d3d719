// The Pareto front on hand-made point sets whose front is known by inspection.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "NonFinite.h"
#include "plot/ParetoFront.h"

namespace shaderbed {
namespace {

using Indices = std::vector<std::size_t>;
using test::kNaN;
using test::kInf;

ParetoFront front_of(const std::vector<CostError>& points) { return find_pareto_front(points); }

TEST(ParetoFront, DominatedPointsAreExcludedAndTheFrontIsOrderedByCost) {
  //  error
  //   4 | 0           3 is beaten by 1 (cheaper and more accurate), 4 by 2
  //   3 |     3
  //   2 |   1     4
  //   1 |       2
  //   0 |         5
  //     +------------ cost
  const std::vector<CostError> points = {{1, 4}, {2, 2}, {3, 1}, {2.5, 3}, {4, 2}, {5, 0}};
  EXPECT_EQ(front_of(points).front, (Indices{0, 1, 2, 5}));
  EXPECT_TRUE(front_of(points).non_finite.empty());
}

TEST(ParetoFront, InputOrderDoesNotMatter) {
  const std::vector<CostError> points = {{5, 0}, {4, 2}, {2.5, 3}, {3, 1}, {2, 2}, {1, 4}};
  EXPECT_EQ(front_of(points).front, (Indices{5, 4, 3, 0}));
}

TEST(ParetoFront, EqualCostKeepsOnlyTheLowestError) {
  const std::vector<CostError> points = {{1, 3}, {1, 2}, {1, 5}, {2, 1}};
  EXPECT_EQ(front_of(points).front, (Indices{1, 3}));
}

TEST(ParetoFront, EqualErrorKeepsOnlyTheLowestCost) {
  const std::vector<CostError> points = {{3, 1}, {2, 1}, {4, 1}, {1, 5}};
  EXPECT_EQ(front_of(points).front, (Indices{3, 1}));
}

TEST(ParetoFront, ExactDuplicatesDoNotDominateEachOther) {
  const std::vector<CostError> points = {{2, 1}, {1, 3}, {2, 1}, {2, 2}};
  EXPECT_EQ(front_of(points).front, (Indices{1, 0, 2}));
  EXPECT_FALSE(dominates(points[0], points[2]));
  EXPECT_TRUE(dominates(points[0], points[3]));
}

TEST(ParetoFront, NonFinitePointsAreNeverOnTheFrontNorDominateButAreKept) {
  // A NaN or -Inf error would "win" any comparison it took part in; it must take part in none.
  const std::vector<CostError> points = {{1, kNaN}, {2, 5}, {0.5, -kInf}, {kInf, 0}, {3, 1}, {kNaN, kNaN}, {-kInf, 9}};
  const ParetoFront f = front_of(points);
  EXPECT_EQ(f.front, (Indices{1, 4}));
  EXPECT_EQ(f.non_finite, (Indices{0, 2, 3, 5, 6}));
}

TEST(ParetoFront, NegativeAndZeroValuesAreOrdinaryNumbers) {
  const std::vector<CostError> points = {{0, 0}, {-1, 2}, {0, -0.0}, {1, -1}};
  EXPECT_EQ(front_of(points).front, (Indices{1, 0, 2, 3}));  // 0 and -0 are the same error
}

TEST(ParetoFront, EmptyAndSinglePointSets) {
  EXPECT_TRUE(front_of({}).front.empty());
  EXPECT_EQ(front_of({{7, 7}}).front, (Indices{0}));
  EXPECT_EQ(front_of({{kNaN, 1}}).non_finite, (Indices{0}));
}

TEST(ParetoFront, EveryExcludedFinitePointIsDominatedByAFrontPoint) {
  // A scattered set, checked against the definition rather than a hand answer.
  std::vector<CostError> points;
  for (int i = 0; i < 200; ++i) points.push_back({double((i * 37) % 23), double((i * 53) % 29)});
  const ParetoFront f = front_of(points);
  ASSERT_FALSE(f.front.empty());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const bool on_front = std::ranges::find(f.front, i) != f.front.end();
    bool dominated = false;
    for (const CostError& other : points) dominated = dominated || dominates(other, points[i]);
    EXPECT_EQ(on_front, !dominated) << "point " << i;
  }
  for (std::size_t k = 1; k < f.front.size(); ++k) EXPECT_LE(points[f.front[k - 1]].cost, points[f.front[k]].cost);
}

// Speeds are medians with confidence intervals: what lies within noise is not ordered.
CostError measured(double cost, double low, double high, double error) { return {cost, error, low, high}; }

TEST(ParetoFront, PointsWhoseCostIntervalsOverlapAreBothOnTheFront) {
  // 1 has the higher median and the higher error, but its interval overlaps 0's: within
  // noise it may be the faster, so 0 does not dominate it.
  const std::vector<CostError> points = {measured(1.0, 0.9, 1.2, 0.1), measured(1.1, 1.0, 1.3, 0.2)};
  EXPECT_EQ(front_of(points).front, (Indices{0, 1}));
  EXPECT_FALSE(dominates(points[0], points[1]));
  EXPECT_FALSE(dominates(points[1], points[0]));
}

TEST(ParetoFront, ADisjointFasterIntervalWithNoWorseErrorDominates) {
  const std::vector<CostError> points = {measured(1.0, 0.9, 1.1, 0.1), measured(2.0, 1.8, 2.2, 0.1),
                                         measured(2.1, 1.95, 2.3, 0.3), measured(3.0, 2.9, 3.1, 0.05)};
  // 1 is beaten by 0 (wholly faster, same error); 2 by 0 and, within noise of 1, only by 0.
  EXPECT_EQ(front_of(points).front, (Indices{0, 3}));
  EXPECT_TRUE(dominates(points[0], points[1]));
  EXPECT_FALSE(dominates(points[1], points[2]));   // overlapping: 1.8..2.2 against 1.95..2.3
}

TEST(ParetoFront, ANonFiniteIntervalBoundKeepsThePointOffTheFront) {
  const std::vector<CostError> points = {measured(1.0, 0.9, kInf, 0.1), {2.0, 0.2}};
  const ParetoFront f = front_of(points);
  EXPECT_EQ(f.front, (Indices{1}));
  EXPECT_EQ(f.non_finite, (Indices{0}));
}

}  // namespace
}  // namespace shaderbed
