#pragma once
// Triangle rasterisation with the rules of Mesa llvmpipe/lavapipe:
//  - viewport: x_win = (x_ndc + 1) / 2 * W, y_win = (1 - y_ndc) / 2 * H (row 0 = top);
//  - coverage from vertex positions snapped to 1/256 pixel, tested exactly in 64-bit
//    integers at pixel centres (x + 0.5, y + 0.5);
//  - top-left fill rule in this y-down space; no face culling; zero-area (after
//    snapping) triangles are dropped;
//  - depth = z_ndc interpolated linearly in window space, test LESS against 1.0, the
//    first of equal-depth triangles wins (submission order, as on the GPU);
//  - perspective-correct barycentric weights.
// The result is a visibility buffer (nearest triangle and its weights per pixel), so
// the caller shades each covered pixel once; with a side-effect-free shader that equals
// shading every fragment that passes the depth test in submission order.
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace reference {

constexpr int subpixel_bits = 8;  // vertex positions snap to 1/256 pixel

struct VisibleSample {
  static constexpr uint32_t no_triangle = UINT32_MAX;
  uint32_t triangle = no_triangle;  // index of the triangle in the index list (index / 3)
  glm::dvec3 weights{0.0};          // perspective-correct weights of its three vertices
  double depth = 1.0;               // window depth z_ndc in [0, 1]

  bool covered() const { return triangle != no_triangle; }
};

struct VisibilityBuffer {
  int width = 0;
  int height = 0;
  std::vector<VisibleSample> samples;  // width * height, row 0 = top

  const VisibleSample& at(int x, int y) const { return samples[static_cast<size_t>(y) * width + x]; }
};

// Window position (x, y in pixels, y down) and depth (z_ndc) of a clip-space position.
glm::dvec3 window_position(const glm::dvec4& clip, int width, int height);

// Rasterises a triangle list given in clip space. Indices must be in range.
VisibilityBuffer rasterise(std::span<const glm::dvec4> clip_positions, std::span<const uint32_t> indices, int width,
                           int height);

}  // namespace reference
