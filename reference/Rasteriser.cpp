#include "reference/Rasteriser.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "reference/Clipping.h"

namespace reference {
namespace {

constexpr int64_t fixed_one = int64_t{1} << subpixel_bits;
constexpr int64_t fixed_half = fixed_one / 2;

// Keeps snapped window coordinates within about 2^20 pixels = 2^28 fixed-point units, so
// edge functions (products of two coordinate differences) stay far inside int64.
constexpr double guard_band_pixels = 1 << 20;

struct WindowVertex {
  glm::dvec2 position;       // unsnapped, pixels, y down: used for interpolation
  int64_t x_fixed, y_fixed;  // snapped to 1/256 pixel: used for coverage
  double depth;
  double inv_w;
  glm::dvec3 weights_over_w;  // original-triangle weights / w, for perspective correction
};

WindowVertex to_window(const ClipVertex& vertex, int width, int height) {
  const glm::dvec3 window = window_position(vertex.position, width, height);
  const double inv_w = 1.0 / vertex.position.w;
  // Round to nearest even, as llvmpipe's lrintf-based snap does.
  return {glm::dvec2(window),
          static_cast<int64_t>(std::nearbyint(window.x * fixed_one)),
          static_cast<int64_t>(std::nearbyint(window.y * fixed_one)),
          window.z,
          inv_w,
          vertex.weights * inv_w};
}

int64_t floor_div(int64_t numerator, int64_t denominator) {
  const int64_t quotient = numerator / denominator;
  return (numerator % denominator != 0 && (numerator < 0) != (denominator < 0)) ? quotient - 1 : quotient;
}

// Edge a -> b of a triangle oriented so that the edge function is positive inside.
// E(p) = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x), exact in fixed point.
struct EdgeFunction {
  int64_t step_x, step_y;  // change of E per pixel to the right / per row down
  int64_t row_start;       // E - bias at the centre of the first pixel of the bounding box

  // With this orientation in y-down space, a top edge is horizontal and runs toward +x,
  // a left edge runs toward -y. A centre exactly on any other edge is outside, which
  // the bias of one fixed-point unit encodes: inside <=> E - bias >= 0.
  EdgeFunction(const WindowVertex& a, const WindowVertex& b, int64_t first_x, int64_t first_y) {
    const int64_t dx = b.x_fixed - a.x_fixed;
    const int64_t dy = b.y_fixed - a.y_fixed;
    const bool top_left = (dy == 0 && dx > 0) || dy < 0;
    step_x = -dy * fixed_one;
    step_y = dx * fixed_one;
    row_start = dx * (first_y - a.y_fixed) - dy * (first_x - a.x_fixed) - (top_left ? 0 : 1);
  }
};

double edge_function(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

void rasterise_triangle(std::array<WindowVertex, 3> v, uint32_t triangle, VisibilityBuffer& buffer) {
  const int64_t snapped_area = (v[1].x_fixed - v[0].x_fixed) * (v[2].y_fixed - v[0].y_fixed) -
                               (v[1].y_fixed - v[0].y_fixed) * (v[2].x_fixed - v[0].x_fixed);
  if (snapped_area == 0) return;
  if (snapped_area < 0) std::swap(v[1], v[2]);  // no culling: draw both windings

  // Pixel range whose centres x * 256 + 128 lie within the snapped bounding box.
  const auto [min_x, max_x] = std::minmax({v[0].x_fixed, v[1].x_fixed, v[2].x_fixed});
  const auto [min_y, max_y] = std::minmax({v[0].y_fixed, v[1].y_fixed, v[2].y_fixed});
  const int64_t x_begin = std::max<int64_t>(0, -floor_div(-(min_x - fixed_half), fixed_one));
  const int64_t y_begin = std::max<int64_t>(0, -floor_div(-(min_y - fixed_half), fixed_one));
  const int64_t x_last = std::min<int64_t>(buffer.width - 1, floor_div(max_x - fixed_half, fixed_one));
  const int64_t y_last = std::min<int64_t>(buffer.height - 1, floor_div(max_y - fixed_half, fixed_one));
  if (x_begin > x_last || y_begin > y_last) return;

  const int64_t first_x = x_begin * fixed_one + fixed_half;
  const int64_t first_y = y_begin * fixed_one + fixed_half;
  // Edge i is opposite vertex i.
  std::array<EdgeFunction, 3> edges{EdgeFunction(v[1], v[2], first_x, first_y),
                                    EdgeFunction(v[2], v[0], first_x, first_y),
                                    EdgeFunction(v[0], v[1], first_x, first_y)};

  // Interpolation uses the unsnapped positions, as llvmpipe's attribute setup does
  // (it builds the plane equations from the float vertex positions). If snapping made
  // a sliver out of a degenerate triangle, fall back to the snapped positions.
  std::array<glm::dvec2, 3> p{v[0].position, v[1].position, v[2].position};
  double area = edge_function(p[0], p[1], p[2]);
  if (area == 0) {
    for (int i = 0; i < 3; ++i) p[i] = glm::dvec2(v[i].x_fixed, v[i].y_fixed) / double(fixed_one);
    area = edge_function(p[0], p[1], p[2]);
  }

  for (int64_t y = y_begin; y <= y_last; ++y) {
    std::array<int64_t, 3> e{edges[0].row_start, edges[1].row_start, edges[2].row_start};
    for (int64_t x = x_begin; x <= x_last; ++x) {
      if ((e[0] | e[1] | e[2]) >= 0) {
        const glm::dvec2 centre(x + 0.5, y + 0.5);
        const glm::dvec3 screen_weights(edge_function(p[1], p[2], centre) / area,
                                        edge_function(p[2], p[0], centre) / area,
                                        edge_function(p[0], p[1], centre) / area);
        const double depth =
            screen_weights[0] * v[0].depth + screen_weights[1] * v[1].depth + screen_weights[2] * v[2].depth;
        VisibleSample& sample = buffer.samples[static_cast<size_t>(y) * buffer.width + x];
        if (depth < sample.depth) {
          const double inv_w =
              screen_weights[0] * v[0].inv_w + screen_weights[1] * v[1].inv_w + screen_weights[2] * v[2].inv_w;
          sample.triangle = triangle;
          sample.depth = depth;
          sample.weights = (screen_weights[0] * v[0].weights_over_w + screen_weights[1] * v[1].weights_over_w +
                            screen_weights[2] * v[2].weights_over_w) /
                           inv_w;
        }
      }
      for (int i = 0; i < 3; ++i) e[i] += edges[i].step_x;
    }
    for (int i = 0; i < 3; ++i) edges[i].row_start += edges[i].step_y;
  }
}

}  // namespace

glm::dvec3 window_position(const glm::dvec4& clip, int width, int height) {
  const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
  return {(ndc.x + 1.0) * 0.5 * width, (1.0 - ndc.y) * 0.5 * height, ndc.z};
}

VisibilityBuffer rasterise(std::span<const glm::dvec4> clip_positions, std::span<const uint32_t> indices, int width,
                           int height) {
  VisibilityBuffer buffer{width, height, std::vector<VisibleSample>(static_cast<size_t>(width) * height)};
  const double guard_band = guard_band_pixels / std::max(width, height);  // in NDC units
  for (size_t first = 0; first + 2 < indices.size(); first += 3) {
    const std::array<ClipVertex, 3> triangle{{
        {clip_positions[indices[first]], {1, 0, 0}},
        {clip_positions[indices[first + 1]], {0, 1, 0}},
        {clip_positions[indices[first + 2]], {0, 0, 1}},
    }};
    // A NaN or infinite vertex has no defined coverage on the GPU either; skipping it
    // keeps the fixed-point conversion defined.
    const auto finite = [](const ClipVertex& v) {
      return std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z) &&
             std::isfinite(v.position.w);
    };
    if (!std::ranges::all_of(triangle, finite)) continue;
    const ClipPolygon polygon = clip_triangle(triangle, guard_band);
    const auto triangle_index = static_cast<uint32_t>(first / 3);
    // A fan over the clipped polygon; the fill rule keeps the inner edges watertight.
    for (int i = 1; i + 1 < polygon.size; ++i) {
      rasterise_triangle({to_window(polygon.vertices[0], width, height), to_window(polygon.vertices[i], width, height),
                          to_window(polygon.vertices[i + 1], width, height)},
                         triangle_index, buffer);
    }
  }
  return buffer;
}

}  // namespace reference
