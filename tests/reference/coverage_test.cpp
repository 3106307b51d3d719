// Coverage: pixel centres at .5, top-left fill rule in y-down space, 1/256 snapping.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "WindowSpace.h"

namespace reference::testing {
namespace {

constexpr int size = 16;

std::vector<int> triangle_coverage(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  const std::vector<glm::dvec4> clip{clip_from_window(a.x, a.y, size, size), clip_from_window(b.x, b.y, size, size),
                                     clip_from_window(c.x, c.y, size, size)};
  const std::vector<uint32_t> indices{0, 1, 2};
  return coverage(clip, indices, size, size);
}

bool covered(const std::vector<int>& coverage, int x, int y) { return coverage[y * size + x] == 1; }

// Legs on pixel boundaries: no centre lies on a leg; the centres x + y = 11 lie exactly
// on the hypotenuse, which is a right edge, so they are out.
TEST(Coverage, RightTriangleWithLegsOnPixelBoundaries) {
  const std::vector<int> coverage = triangle_coverage({2, 2}, {10, 2}, {2, 10});
  int expected = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double cx = x + 0.5, cy = y + 0.5;
      const bool inside = cx > 2 && cy > 2 && cx + cy < 12;  // strict: the hypotenuse is not top-left
      expected += inside;
      EXPECT_EQ(covered(coverage, x, y), inside) << "pixel " << x << "," << y;
    }
  }
  EXPECT_EQ(expected, 28);  // 1 + 2 + ... + 7
  EXPECT_EQ(count(coverage), expected);
}

TEST(Coverage, BothWindingsCoverTheSamePixels) {
  EXPECT_EQ(triangle_coverage({2, 2}, {10, 2}, {2, 10}), triangle_coverage({2, 2}, {2, 10}, {10, 2}));
  EXPECT_EQ(triangle_coverage({1.3, 0.7}, {13.1, 5.2}, {4.4, 14.9}),
            triangle_coverage({4.4, 14.9}, {13.1, 5.2}, {1.3, 0.7}));
}

// Edges through pixel centres: the top edge (row 2) and left edge (column 2) are in.
TEST(Coverage, CentresOnTopAndLeftEdgesAreCovered) {
  const std::vector<int> coverage = triangle_coverage({2.5, 2.5}, {10.5, 2.5}, {2.5, 10.5});
  EXPECT_TRUE(covered(coverage, 5, 2)) << "centre on the top edge";
  EXPECT_TRUE(covered(coverage, 2, 5)) << "centre on the left edge";
  EXPECT_FALSE(covered(coverage, 6, 6)) << "centre on the hypotenuse (a right edge)";
  // x >= 2, y >= 2, and strictly below the hypotenuse: (x+.5) + (y+.5) < 13.
  EXPECT_EQ(count(coverage), 36);  // 1 + 2 + ... + 8
}

// Mirror image: a horizontal bottom edge through row 10 and a right edge through column
// 10, both out; the hypotenuse is now this triangle's left edge, so it is in.
TEST(Coverage, CentresOnBottomAndRightEdgesAreNotCovered) {
  const std::vector<int> coverage = triangle_coverage({10.5, 10.5}, {2.5, 10.5}, {10.5, 2.5});
  EXPECT_FALSE(covered(coverage, 7, 10)) << "centre on the bottom edge";
  EXPECT_FALSE(covered(coverage, 10, 7)) << "centre on the right edge";
  EXPECT_TRUE(covered(coverage, 6, 6)) << "centre on the hypotenuse (a left edge)";
  EXPECT_TRUE(covered(coverage, 9, 9));
  EXPECT_EQ(count(coverage), 28);  // x, y <= 9 and (x+.5) + (y+.5) >= 13
}

// Two triangles sharing the diagonal of a square through pixel centres: every centre of
// the square [2.5, 10.5)^2 exactly once, nothing outside it.
TEST(Coverage, SharedEdgeCoversEachPixelExactlyOnce) {
  const std::vector<int> upper = triangle_coverage({2.5, 2.5}, {10.5, 2.5}, {2.5, 10.5});
  const std::vector<int> lower = triangle_coverage({10.5, 10.5}, {2.5, 10.5}, {10.5, 2.5});
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const bool in_square = x >= 2 && x <= 9 && y >= 2 && y <= 9;
      EXPECT_EQ(upper[y * size + x] + lower[y * size + x], in_square ? 1 : 0) << "pixel " << x << "," << y;
    }
  }
}

// A mesh of jittered quads (interior vertices off the grid, at arbitrary sub-pixel
// positions): each triangle rasterised on its own, every pixel of the region exactly once.
TEST(Coverage, JitteredMeshIsWatertightWithoutOverlap) {
  constexpr int cells = 4;
  constexpr double cell = 3.0, origin = 2.0;  // region [2, 14)^2, border on pixel boundaries
  uint32_t state = 12345;
  auto jitter = [&] {
    state = state * 1664525u + 1013904223u;
    return (double(state >> 8) / double(1u << 24) - 0.5) * 1.6;
  };
  std::vector<glm::dvec2> points;
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) {
      glm::dvec2 p(origin + i * cell, origin + j * cell);
      if (i > 0 && i < cells) p.x += jitter();
      if (j > 0 && j < cells) p.y += jitter();
      points.push_back(p);
    }
  }
  std::vector<int> total(size * size, 0);
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      const int a = j * (cells + 1) + i, b = a + 1, c = a + cells + 1, d = c + 1;
      // Alternate the diagonal so both diagonal directions are exercised.
      const std::array<std::array<int, 3>, 2> triangles =
          (i + j) % 2 ? std::array<std::array<int, 3>, 2>{{{a, b, d}, {a, d, c}}}
                      : std::array<std::array<int, 3>, 2>{{{a, b, c}, {b, d, c}}};
      for (const auto& t : triangles) {
        const std::vector<int> one = triangle_coverage(points[t[0]], points[t[1]], points[t[2]]);
        for (size_t k = 0; k < total.size(); ++k) total[k] += one[k];
      }
    }
  }
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const bool in_region = x >= 2 && x < 14 && y >= 2 && y < 14;
      EXPECT_EQ(total[y * size + x], in_region ? 1 : 0) << "pixel " << x << "," << y;
    }
  }
}

// Vertices snap to the nearest 1/256 pixel, so centres within half a step of an edge
// count as on it. Left edge 1/1024 right of the column-2 centres: snaps onto them, in.
// 3/1024 right: snaps a full step right of them, out (truncation would put it on them).
// Right edge 1/1024 right of the column-10 centres: snaps onto them, out. Unsnapped,
// the first and last would come out the other way.
TEST(Coverage, VerticesSnapToTheNearestTwoHundredFiftySixthOfAPixel) {
  const double onto_left = 2.5 + 1.0 / 1024;
  EXPECT_TRUE(covered(triangle_coverage({onto_left, 2}, {10, 2}, {onto_left, 10}), 2, 4));
  const double past_left = 2.5 + 3.0 / 1024;
  const std::vector<int> past = triangle_coverage({past_left, 2}, {10, 2}, {past_left, 10});
  EXPECT_FALSE(covered(past, 2, 4));
  EXPECT_TRUE(covered(past, 3, 4));
  const double onto_right = 10.5 + 1.0 / 1024;
  const std::vector<int> right = triangle_coverage({2, 2}, {onto_right, 2}, {onto_right, 10});
  EXPECT_FALSE(covered(right, 10, 8));
  EXPECT_TRUE(covered(right, 9, 8));
}

TEST(Coverage, ZeroAreaTriangleCoversNothing) {
  EXPECT_EQ(count(triangle_coverage({2.5, 2.5}, {10.5, 10.5}, {6.5, 6.5})), 0);
}

TEST(Coverage, TriangleWithANonFiniteVertexIsSkipped) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<glm::dvec4> clip{{-1, 1, 0.5, 1}, {1, 1, 0.5, 1}, {nan, -1, 0.5, 1}};
  const std::vector<uint32_t> indices{0, 1, 2};
  EXPECT_EQ(count(coverage(clip, indices, size, size)), 0);
}

// Row 0 is the top of the image: NDC y = +1.
TEST(Coverage, NdcYUpIsImageRowZero) {
  const std::vector<glm::dvec4> clip{{-1, 1, 0.5, 1}, {1, 1, 0.5, 1}, {-1, 0.5, 0.5, 1}};
  const std::vector<uint32_t> indices{0, 1, 2};
  const std::vector<int> c = coverage(clip, indices, size, size);
  EXPECT_TRUE(covered(c, 0, 0));
  EXPECT_FALSE(covered(c, 0, size - 1));
}

}  // namespace
}  // namespace reference::testing
