// The scene's light and ambient term around any model (Scene::light, Scene::ambient):
// a floor plane y = 0 under the point light at (0, 50, 0), each pixel's surface point
// found by casting its ray at the plane (independently of the rasteriser), and the
// colour worked out by hand from it.
#include <gtest/gtest.h>

#include <cmath>

#include "PixelRays.h"
#include "reference/Reference.h"

namespace reference {
namespace {

constexpr int kSize = 48;

// A 200 x 200 floor at y = 0 facing up, as two triangles.
Scene floor_scene() {
  Scene s;
  const glm::dvec3 up{0, 1, 0}, t{1, 0, 0};
  for (const glm::dvec3& p : {glm::dvec3(-100, 0, -100), glm::dvec3(100, 0, -100), glm::dvec3(100, 0, 100),
                              glm::dvec3(-100, 0, 100)})
    s.mesh.vertices.push_back({p, up, t, {0, 0}});
  s.mesh.indices = {0, 1, 2, 0, 2, 3};
  s.width = s.height = kSize;
  return s;
}

// Every covered pixel's colour against `expected(P)` at its floor point P.
template <typename Expected>
void expect_floor(const Scene& scene, const std::string& model, const Params& params, Expected expected,
                  Mode mode = Mode::per_pixel) {
  auto image = render(scene, model, mode, params);
  ASSERT_TRUE(image) << image.error();
  const glm::dmat4 world_to_clip = projection_matrix(scene.camera, 1.0) * view_matrix(scene.camera);
  int covered = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const size_t pixel = size_t(y) * kSize + x;
      if (!image->coverage[pixel]) continue;
      ++covered;
      const glm::dvec3 p = testing::pixel_ray_hit(world_to_clip, scene.camera.eye, kSize, kSize, x, y, {0, 0, 0}, {0, 1, 0});
      const glm::dvec3 want = expected(p);
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(image->rgba[pixel * 4 + k], want[k], 1e-7) << model << " at " << x << "," << y;
    }
  EXPECT_GT(covered, kSize * kSize / 4);
}

const glm::dvec3 scene_diffuse{0.9, 0.7, 0.5};
const Params scene_lambert{{"diffuse", {0.9, 0.7, 0.5}}};

TEST(SceneLight, LambertUsesItsDirectionalLightByDefault) {
  // The light from +Y on a floor facing +Y: N.L = 1 everywhere.
  expect_floor(floor_scene(), "lambert", scene_lambert, [](const glm::dvec3&) { return scene_diffuse; });
  Scene directional = floor_scene();
  directional.light = SceneLight::directional;
  expect_floor(directional, "lambert", scene_lambert, [](const glm::dvec3&) { return scene_diffuse; });
}

TEST(SceneLight, PointMakesLambertFallOffAsTheCosineToTheLight) {
  Scene s = floor_scene();
  s.light = SceneLight::point;
  // L = normalize((0, 50, 0) - P) with P = (x, 0, z): N.L = 50 / |(0, 50, 0) - P|.
  expect_floor(s, "lambert", scene_lambert, [](const glm::dvec3& p) { return scene_diffuse * (50.0 / glm::length(glm::dvec3(0, 50, 0) - p)); });
}

TEST(SceneLight, PointLightOnPhongMovesTheHighlight) {
  Scene s = floor_scene();
  s.light = SceneLight::point;
  const Params phong{{"diffuse", {0.5, 0.5, 0.5}}, {"specular", {1, 1, 1}}, {"power", {7}}};
  expect_floor(s, "phong", phong, [&](const glm::dvec3& p) {
    const glm::dvec3 n{0, 1, 0};
    const glm::dvec3 l = glm::normalize(glm::dvec3(0, 50, 0) - p);
    const glm::dvec3 v = glm::normalize(s.camera.eye - p);
    const glm::dvec3 r = glm::normalize(2.0 * n * glm::dot(n, l) - l);
    return glm::dvec3(0.5) * std::max(0.0, glm::dot(n, l)) + glm::dvec3(std::pow(std::max(0.0, glm::dot(r, v)), 7.0));
  });
}

TEST(SceneLight, APointLightInATranslatedObjectIsMovedIntoObjectSpace) {
  // The floor drawn 10 units lower: in object space the light is 60 above it.
  Scene s = floor_scene();
  s.light = SceneLight::point;
  s.world = glm::dmat4(1.0);
  s.world[3] = glm::dvec4(0, -10, 0, 1);
  auto image = render(s, "lambert", Mode::per_pixel, scene_lambert);
  ASSERT_TRUE(image) << image.error();
  const glm::dmat4 world_to_clip = projection_matrix(s.camera, 1.0) * view_matrix(s.camera);
  const int x = kSize / 2, y = kSize * 3 / 4;   // below the image centre: on the floor
  const size_t pixel = size_t(y) * kSize + x;
  ASSERT_TRUE(image->coverage[pixel]);
  const glm::dvec3 p = testing::pixel_ray_hit(world_to_clip, s.camera.eye, kSize, kSize, x, y, {0, -10, 0}, {0, 1, 0});
  EXPECT_NEAR(image->rgba[pixel * 4], 0.9 * 60.0 / glm::length(glm::dvec3(0, 50, 0) - p), 1e-7);
}

TEST(SceneLight, AmbientIsAddedToEveryModelPerPixelAndPerVertex) {
  Scene s = floor_scene();
  s.ambient = {0.1, 0.2, 0.3};
  for (Mode mode : {Mode::per_pixel, Mode::per_vertex})
    expect_floor(s, "lambert", scene_lambert, [](const glm::dvec3&) { return scene_diffuse + glm::dvec3(0.1, 0.2, 0.3); }, mode);
  // The ambient model's own colour and the scene's add up.
  expect_floor(s, "ambient", {{"ambient", {0.2, 0.3, 0.4}}},
               [](const glm::dvec3&) { return glm::dvec3(0.3, 0.5, 0.7); });
}

TEST(SceneLight, PointLightModelsKeepThePointLightAndRefuseTheDirectionalOne) {
  const Params point{{"diffuse", {0.9, 0.7, 0.5}}, {"light_color", {1, 1, 1}}, {"attenuation", {0, 0.04, 0}}};
  Scene s = floor_scene();
  s.light = SceneLight::point;
  // point_attenuated's defaults (0, 0.04, 0): D sat(N.Lp) / (0.04 d).
  expect_floor(s, "point_attenuated", point, [](const glm::dvec3& p) {
    const double d = glm::length(glm::dvec3(0, 50, 0) - p);
    return scene_diffuse * (50.0 / d) / (0.04 * d);
  });
  s.light = SceneLight::directional;
  for (const char* model : {"point_attenuated", "spot", "warn"}) {
    const auto params = default_params(model);
    ASSERT_TRUE(params) << params.error();
    auto image = render(s, model, Mode::per_pixel, *params);
    ASSERT_FALSE(image) << model;
    EXPECT_NE(image.error().find("point light"), std::string::npos) << image.error();
  }
}

}  // namespace
}  // namespace reference
