// render() end to end: errors, the framebuffer's channels, per-vertex and per-pixel
// shading against analytic values, a closed mesh without holes, and speed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/ext/matrix_transform.hpp>
#include <numbers>

#include "PixelRays.h"
#include "UvSphere.h"
#include "reference/Reference.h"

namespace reference {
namespace {

Scene sphere_scene() {
  Scene scene;
  scene.mesh = test::uv_sphere(64, 32);  // 4096 triangles
  scene.camera.eye = {0, 0, -5};
  scene.camera.target = {0, 0, 0};
  return scene;
}

const Params render_phong{{"diffuse", {0.6, 0.5, 0.4}}, {"specular", {1, 1, 1}}, {"power", {7}}};

TEST(Render, ErrorsComeBackAsText) {
  Scene scene = sphere_scene();
  const auto unknown = render(scene, "no-such-model", Mode::per_pixel, {});
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().find("no-such-model"), std::string::npos);

  const auto missing = render(scene, "phong", Mode::per_vertex, {{"diffuse", {1, 1, 1}}, {"power", {7}}});
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error(), "phong: missing parameter 'specular'");

  scene.mesh.indices.push_back(static_cast<uint32_t>(scene.mesh.vertices.size()));
  scene.mesh.indices.push_back(0);
  scene.mesh.indices.push_back(1);
  const auto out_of_range = render(scene, "phong", Mode::per_pixel, render_phong);
  ASSERT_FALSE(out_of_range);
  EXPECT_NE(out_of_range.error().find("out of range"), std::string::npos);
}

// The sphere's silhouette is a circle of radius tan(asin(1/5)) / tan(22.5 deg) in NDC.
// Every pixel well inside it is covered (no cracks), none well outside; covered pixels
// have alpha 1 and coverage 1, the others are all zero.
TEST(Render, ClosedMeshCoversItsSilhouetteWithoutHolesAndSetsAlphaAndCoverage) {
  const Scene scene = sphere_scene();
  const auto image = render(scene, "phong", Mode::per_pixel, render_phong);
  ASSERT_TRUE(image) << image.error();
  ASSERT_EQ(image->rgba.size(), size_t{256} * 256 * 4);
  ASSERT_EQ(image->coverage.size(), size_t{256} * 256);
  const double radius_pixels = std::tan(std::asin(0.2)) / std::tan(glm::radians(22.5)) * 128;
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      const size_t pixel = size_t(y) * 256 + x;
      const double r = std::hypot(x + 0.5 - 128, y + 0.5 - 128);
      if (r < radius_pixels * 0.97) {
        ASSERT_EQ(image->coverage[pixel], 1) << x << "," << y;
      }
      if (r > radius_pixels * 1.01) {
        ASSERT_EQ(image->coverage[pixel], 0) << x << "," << y;
      }
      if (image->coverage[pixel]) {
        EXPECT_EQ(image->rgba[pixel * 4 + 3], 1.0);
        for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(image->rgba[pixel * 4 + c]));
      } else {
        for (int c = 0; c < 4; ++c) ASSERT_EQ(image->rgba[pixel * 4 + c], 0.0);
      }
    }
  }
}

// One triangle, seen obliquely, under a rotated and translated world matrix, with
// different vertex normals. At each covered pixel the expected colour comes from the
// barycentric coordinates of the pixel ray's hit point on the triangle.
class ShadingAgainstRayHits : public ::testing::Test {
 protected:
  void SetUp() override {
    scene.width = 64;
    scene.height = 64;
    scene.camera.eye = {-30, 40, -10};
    scene.camera.target = {0, 0, 0};
    scene.world =
        glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(2, -1, 3)), glm::radians(90.0), glm::dvec3(0, 0, 1));
    scene.lights.direction = glm::normalize(glm::dvec3(0.3, 1, 0.2));
    const std::array<glm::dvec3, 3> positions{{{-2, -20, -20}, {1, 20, -5}, {3, 0, 25}}};
    const std::array<glm::dvec3, 3> normals{{{1, 0, 0}, {0.6, 0.8, 0}, {0.3, -0.3, 0.9}}};  // not all unit
    for (int i = 0; i < 3; ++i) scene.mesh.vertices.push_back({positions[i], normals[i], {0, 0, 1}, {0, 0}});
    scene.mesh.indices = {0, 1, 2};
    object_light = glm::normalize(glm::dvec3(glm::inverse(scene.world) * glm::dvec4(scene.lights.direction, 0)));
  }

  // Calls expected(barycentrics) at every covered pixel and compares.
  template <typename Expected>
  void check(Mode mode, Expected expected) {
    const auto image = render(scene, "lambert", mode, params);
    ASSERT_TRUE(image) << image.error();
    const glm::dmat4 world_to_clip = projection_matrix(scene.camera, 1.0) * view_matrix(scene.camera);
    const auto& v = scene.mesh.vertices;
    const glm::dvec3 a = glm::dvec3(scene.world * glm::dvec4(v[0].position, 1));
    const glm::dvec3 b = glm::dvec3(scene.world * glm::dvec4(v[1].position, 1));
    const glm::dvec3 c = glm::dvec3(scene.world * glm::dvec4(v[2].position, 1));
    const glm::dvec3 n = glm::cross(b - a, c - a);
    int covered = 0;
    for (int y = 0; y < scene.height; ++y) {
      for (int x = 0; x < scene.width; ++x) {
        const size_t pixel = size_t(y) * scene.width + x;
        if (!image->coverage[pixel]) continue;
        ++covered;
        const glm::dvec3 q =
            testing::pixel_ray_hit(world_to_clip, scene.camera.eye, scene.width, scene.height, x, y, a, n);
        const glm::dvec3 weights(glm::dot(glm::cross(c - b, q - b), n) / glm::dot(n, n),
                                 glm::dot(glm::cross(a - c, q - c), n) / glm::dot(n, n), 0.0);
        const glm::dvec3 colour = expected(glm::dvec3(weights.x, weights.y, 1 - weights.x - weights.y));
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(image->rgba[pixel * 4 + k], colour[k], 1e-9) << x << "," << y;
      }
    }
    EXPECT_GT(covered, 200);
  }

  Scene scene;
  glm::dvec3 object_light;
  const glm::dvec3 diffuse{0.9, 0.7, 0.5};
  const Params params{{"diffuse", {0.9, 0.7, 0.5}}};
};

TEST_F(ShadingAgainstRayHits, PerVertexInterpolatesVertexColoursPerspectiveCorrectly) {
  std::array<glm::dvec3, 3> vertex_colours;
  for (int i = 0; i < 3; ++i) {
    vertex_colours[i] = diffuse * std::max(0.0, glm::dot(glm::normalize(scene.mesh.vertices[i].normal), object_light));
  }
  check(Mode::per_vertex, [&](const glm::dvec3& w) {
    return w[0] * vertex_colours[0] + w[1] * vertex_colours[1] + w[2] * vertex_colours[2];
  });
}

TEST_F(ShadingAgainstRayHits, PerPixelShadesTheNormalisedInterpolatedNormal) {
  check(Mode::per_pixel, [&](const glm::dvec3& w) {
    const auto& v = scene.mesh.vertices;
    const glm::dvec3 normal = glm::normalize(w[0] * v[0].normal + w[1] * v[1].normal + w[2] * v[2].normal);
    return diffuse * std::max(0.0, glm::dot(normal, object_light));
  });
}

}  // namespace
}  // namespace reference
