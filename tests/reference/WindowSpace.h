#pragma once
// Test helpers: place vertices directly in window space (pixels, y down) so coverage
// can be worked out by hand. With w = 1 the clip position is the NDC position, and for
// the power-of-two image sizes used here the mapping back to window space is exact.
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "reference/Rasteriser.h"

namespace reference::testing {

inline glm::dvec4 clip_from_window(double x, double y, int width, int height, double depth = 0.5) {
  return {2.0 * x / width - 1.0, 1.0 - 2.0 * y / height, depth, 1.0};
}

// Coverage of a single triangle list, 1/0 per pixel, row 0 = top.
inline std::vector<int> coverage(std::span<const glm::dvec4> clip, std::span<const uint32_t> indices, int width,
                                 int height) {
  const VisibilityBuffer buffer = rasterise(clip, indices, width, height);
  std::vector<int> covered(buffer.samples.size());
  for (size_t i = 0; i < covered.size(); ++i) covered[i] = buffer.samples[i].covered() ? 1 : 0;
  return covered;
}

inline int count(const std::vector<int>& coverage) {
  int total = 0;
  for (int c : coverage) total += c;
  return total;
}

}  // namespace reference::testing
