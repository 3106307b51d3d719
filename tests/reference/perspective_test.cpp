// Perspective-correct interpolation and near-plane clipping, checked against the
// analytic intersection of each pixel's ray with the geometry's plane.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "PixelRays.h"
#include "reference/Rasteriser.h"
#include "reference/Reference.h"

namespace reference {
namespace {

constexpr int width = 64, height = 48;

struct Projected {
  std::vector<glm::dvec4> clip;
  glm::dmat4 world_to_clip;
};

Projected project(const Camera& camera, const std::vector<glm::dvec3>& world_positions) {
  const glm::dmat4 world_to_clip = projection_matrix(camera, double(width) / height) * view_matrix(camera);
  Projected result{{}, world_to_clip};
  for (const glm::dvec3& p : world_positions) result.clip.push_back(world_to_clip * glm::dvec4(p, 1.0));
  return result;
}

glm::dvec3 ray_hit(const Projected& projected, const Camera& camera, int x, int y, const glm::dvec3& plane_point,
                   const glm::dvec3& plane_normal) {
  return testing::pixel_ray_hit(projected.world_to_clip, camera.eye, width, height, x, y, plane_point, plane_normal);
}

// Screen-linear (affine) interpolation, which perspective correction must beat.
glm::dvec3 affine_position(const std::vector<glm::dvec4>& clip, const std::vector<glm::dvec3>& world,
                           const std::array<uint32_t, 3>& corners, int x, int y) {
  std::array<glm::dvec2, 3> p;
  for (int i = 0; i < 3; ++i) p[i] = glm::dvec2(window_position(clip[corners[i]], width, height));
  const auto edge = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  };
  const glm::dvec2 centre(x + 0.5, y + 0.5);
  const double area = edge(p[0], p[1], p[2]);
  return edge(p[1], p[2], centre) / area * world[corners[0]] + edge(p[2], p[0], centre) / area * world[corners[1]] +
         edge(p[0], p[1], centre) / area * world[corners[2]];
}

glm::dvec3 interpolated(const VisibleSample& sample, const std::vector<glm::dvec3>& world,
                        const std::vector<uint32_t>& indices) {
  const size_t first = size_t{sample.triangle} * 3;
  return sample.weights[0] * world[indices[first]] + sample.weights[1] * world[indices[first + 1]] +
         sample.weights[2] * world[indices[first + 2]];
}

// A quad tilted 60 degrees away from the viewer, its far end five times as far as its
// near end: the interpolated position at every covered pixel is the ray's hit point.
TEST(Perspective, InterpolatedPositionIsTheRayHitOnATiltedQuad) {
  Camera camera;
  camera.eye = {0, 0, -10};
  camera.target = {0, 0, 0};
  const double s = std::sin(glm::radians(60.0)), c = std::cos(glm::radians(60.0));
  const glm::dvec3 along(0, c * 8, s * 8);  // from the quad's near edge to its far edge
  const std::vector<glm::dvec3> world{
      {-3, -3, -4}, {3, -3, -4}, glm::dvec3(-3, -3, -4) + along, glm::dvec3(3, -3, -4) + along};
  const std::vector<uint32_t> indices{0, 1, 2, 1, 3, 2};
  const glm::dvec3 normal = glm::normalize(glm::cross(world[1] - world[0], world[2] - world[0]));
  const Projected projected = project(camera, world);
  const VisibilityBuffer buffer = rasterise(projected.clip, indices, width, height);

  int covered = 0;
  double largest_affine_error = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const VisibleSample& sample = buffer.at(x, y);
      if (!sample.covered()) continue;
      ++covered;
      const glm::dvec3 expected = ray_hit(projected, camera, x, y, world[0], normal);
      EXPECT_NEAR(glm::distance(interpolated(sample, world, indices), expected), 0.0, 1e-9) << x << "," << y;
      const size_t first = size_t{sample.triangle} * 3;
      const glm::dvec3 affine =
          affine_position(projected.clip, world, {indices[first], indices[first + 1], indices[first + 2]}, x, y);
      largest_affine_error = std::max(largest_affine_error, glm::distance(affine, expected));
    }
  }
  EXPECT_GT(covered, 300);
  // The set-up is steep enough that screen-linear interpolation would be far off.
  EXPECT_GT(largest_affine_error, 0.5);
}

// A ground plane that extends behind the eye: it must be clipped at the near plane, not
// wrapped through w <= 0, and what remains still interpolates to the ray hits.
TEST(Perspective, TriangleCrossingTheNearPlaneIsClipped) {
  Camera camera;  // the book's: eye (-100, 50, 0) looking at the origin
  const std::vector<glm::dvec3> world{{-400, 0, -300}, {300, 0, -300}, {-400, 0, 300}, {300, 0, 300}};
  const std::vector<uint32_t> indices{0, 1, 2, 1, 3, 2};
  const Projected projected = project(camera, world);
  const VisibilityBuffer buffer = rasterise(projected.clip, indices, width, height);

  int covered = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const VisibleSample& sample = buffer.at(x, y);
      if (!sample.covered()) continue;
      ++covered;
      const glm::dvec3 expected = ray_hit(projected, camera, x, y, {0, 0, 0}, {0, 1, 0});
      EXPECT_NEAR(glm::distance(interpolated(sample, world, indices), expected), 0.0, 1e-6) << x << "," << y;
      EXPECT_GE(sample.depth, 0.0);
      EXPECT_LT(sample.depth, 1.0);
    }
  }
  // The camera looks down at the plane: the bottom row sees it, the top row looks past
  // its far edge.
  EXPECT_TRUE(buffer.at(width / 2, height - 1).covered());
  EXPECT_FALSE(buffer.at(width / 2, 0).covered());
  EXPECT_GT(covered, width * height / 4);
}

// A plane through the near plane's centre at 45 degrees: its left half of the view lies
// between the eye and the near plane (w > 0, z_ndc < 0) and must be clipped away, its
// right half beyond it is drawn. The clipped edge falls on the pixel boundary x = W/2.
TEST(Perspective, GeometryNearerThanTheNearPlaneIsClippedAway) {
  Camera camera;
  camera.eye = {0, 0, -10};
  camera.target = {0, 0, 0};  // forward +z, screen right is world +x; near plane z = -9
  const std::vector<glm::dvec3> world{{-20, -20, -29}, {20, -20, 11}, {0, 30, -9}};  // plane z = x - 9
  const std::vector<uint32_t> indices{0, 1, 2};
  const VisibilityBuffer buffer = rasterise(project(camera, world).clip, indices, width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      EXPECT_EQ(buffer.at(x, y).covered(), x >= width / 2) << x << "," << y;
      if (buffer.at(x, y).covered()) {
        EXPECT_GE(buffer.at(x, y).depth, 0.0);
      }
    }
  }
}

TEST(Perspective, TriangleEntirelyBehindTheEyeCoversNothing) {
  Camera camera;
  camera.eye = {0, 0, -10};
  const std::vector<glm::dvec3> world{{-3, -3, -20}, {3, -3, -20}, {0, 3, -20}};
  const std::vector<uint32_t> indices{0, 1, 2};
  const VisibilityBuffer buffer = rasterise(project(camera, world).clip, indices, width, height);
  for (const VisibleSample& sample : buffer.samples) EXPECT_FALSE(sample.covered());
}

}  // namespace
}  // namespace reference
