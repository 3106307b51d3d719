// Depth test LESS against a buffer cleared to 1.0: the nearer surface wins whatever the
// submission order; equal depth keeps the first; beyond the far plane nothing is drawn.
#include <gtest/gtest.h>

#include <vector>

#include "WindowSpace.h"
#include "reference/Reference.h"

namespace reference {
namespace {

constexpr int depth_size = 16;

std::vector<glm::dvec4> two_overlapping_triangles(double first_depth, double second_depth) {
  using testing::clip_from_window;
  return {clip_from_window(1, 1, depth_size, depth_size, first_depth),    clip_from_window(15, 1, depth_size, depth_size, first_depth),
          clip_from_window(1, 15, depth_size, depth_size, first_depth),   clip_from_window(3, 3, depth_size, depth_size, second_depth),
          clip_from_window(15, 15, depth_size, depth_size, second_depth), clip_from_window(1, 15, depth_size, depth_size, second_depth)};
}

TEST(Depth, NearerTriangleWinsInEitherOrder) {
  const std::vector<uint32_t> indices{0, 1, 2, 3, 4, 5};
  for (const auto& [first_depth, second_depth, winner] :
       std::vector<std::tuple<double, double, uint32_t>>{{0.25, 0.75, 0}, {0.75, 0.25, 1}}) {
    const VisibilityBuffer buffer =
        rasterise(two_overlapping_triangles(first_depth, second_depth), indices, depth_size, depth_size);
    const VisibleSample& overlap = buffer.at(4, 6);  // centre (4.5, 6.5) is inside both triangles
    ASSERT_TRUE(overlap.covered());
    EXPECT_EQ(overlap.triangle, winner);
    EXPECT_DOUBLE_EQ(overlap.depth, std::min(first_depth, second_depth));
  }
}

TEST(Depth, EqualDepthKeepsTheFirstTriangle) {
  const std::vector<uint32_t> indices{0, 1, 2, 3, 4, 5};
  const VisibilityBuffer buffer = rasterise(two_overlapping_triangles(0.5, 0.5), indices, depth_size, depth_size);
  EXPECT_EQ(buffer.at(4, 6).triangle, 0u);
}

TEST(Depth, DepthAtOrBeyondOneIsNotDrawn) {
  const std::vector<uint32_t> indices{0, 1, 2};
  EXPECT_FALSE(rasterise(two_overlapping_triangles(1.0, 1.0), indices, depth_size, depth_size).at(4, 6).covered());
  EXPECT_FALSE(rasterise(two_overlapping_triangles(1.5, 1.5), indices, depth_size, depth_size).at(4, 6).covered());
}

// Through render(): a lit quad in front of an unlit one (Lambert, light from +y).
TEST(Depth, RenderShowsTheNearerQuad) {
  auto quad = [](double z, const glm::dvec3& normal, Mesh& mesh) {
    const auto first = static_cast<uint32_t>(mesh.vertices.size());
    for (const glm::dvec2 corner : {glm::dvec2(-5, -5), glm::dvec2(5, -5), glm::dvec2(-5, 5), glm::dvec2(5, 5)}) {
      mesh.vertices.push_back({{corner.x, corner.y, z}, normal, {1, 0, 0}, {0, 0}});
    }
    for (uint32_t i : {0u, 1u, 2u, 1u, 3u, 2u}) mesh.indices.push_back(first + i);
  };
  for (bool lit_first : {true, false}) {
    Scene scene;
    scene.camera.eye = {0, 0, -20};
    scene.camera.target = {0, 0, 0};
    scene.width = scene.height = 32;
    scene.lights.direction = {0, 1, 0};
    // The lit quad faces the light and is nearer the eye (z = -2 vs z = +2).
    if (lit_first) {
      quad(-2, {0, 1, 0}, scene.mesh);
      quad(2, {0, -1, 0}, scene.mesh);
    } else {
      quad(2, {0, -1, 0}, scene.mesh);
      quad(-2, {0, 1, 0}, scene.mesh);
    }
    const auto image = render(scene, "lambert", Mode::per_pixel, {{"diffuse", {0.5, 0.6, 0.7}}});
    ASSERT_TRUE(image) << image.error();
    const size_t centre = (16 * 32 + 16) * 4;
    EXPECT_DOUBLE_EQ(image->rgba[centre + 0], 0.5) << "lit quad submitted first: " << lit_first;
    EXPECT_DOUBLE_EQ(image->rgba[centre + 1], 0.6);
    EXPECT_DOUBLE_EQ(image->rgba[centre + 2], 0.7);
  }
}

}  // namespace
}  // namespace reference
