// render_surface() and render() under a Perturbation: the surface covers exactly the
// pixels render() shades, its N·L reproduces lambert, and each perturbation changes the
// image the way its convention says (and only that way).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "UvSphere.h"
#include "reference/Reference.h"
#include "reference/Surface.h"
#include "reference/VisibleSurface.h"

namespace reference {
namespace {

// The sphere seen from the side, lit from the upper left so both the lit and the unlit
// side are in view.
Scene tessellated_sphere_scene(int slices, int stacks) {
  Scene scene;
  scene.mesh = test::uv_sphere(slices, stacks);
  scene.width = 96;
  scene.height = 96;
  scene.camera.eye = {0, 0, -5};
  scene.camera.target = {0, 0, 0};
  scene.lights.direction = glm::normalize(glm::dvec3(-1, 1, 0.3));
  scene.lights.position = {-3, 2, -2};
  return scene;
}

const glm::dvec3 surface_diffuse{0.9, 0.6, 0.3};
const Params surface_lambert{{"diffuse", {0.9, 0.6, 0.3}}};
const Params phong{{"diffuse", {0.9, 0.6, 0.3}}, {"specular", {1, 1, 1}}, {"power", {7}}};

Framebuffer rendered(const Scene& scene, const std::string& model, const Params& params,
                     const Perturbation& perturbation = {}, Mode mode = Mode::per_pixel) {
  auto image = render(scene, model, mode, params, perturbation);
  EXPECT_TRUE(image) << image.error();
  return image ? *image : Framebuffer{};
}

SurfaceBuffer surface_of(const Scene& scene) {
  auto surface = render_surface(scene);
  EXPECT_TRUE(surface) << surface.error();
  return surface ? *surface : SurfaceBuffer{};
}

// Calls expected(sample) at every covered pixel and compares the image's RGB with it.
template <typename Expected>
void expect_pixels(const Framebuffer& image, const SurfaceBuffer& surface, Expected expected,
                   double tolerance = 1e-12) {
  ASSERT_EQ(image.coverage, surface.coverage);
  size_t covered = 0;
  for (size_t pixel = 0; pixel < surface.samples.size(); ++pixel) {
    if (!surface.coverage[pixel]) continue;
    ++covered;
    const glm::dvec3 colour = expected(surface.samples[pixel]);
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(image.rgba[pixel * 4 + c], colour[c], tolerance) << "pixel " << pixel;
  }
  EXPECT_GT(covered, 1000u);
}

double n_dot_l(const SurfaceSample& sample) { return glm::dot(glm::normalize(sample.normal), sample.to_light); }

TEST(Surface, CoversExactlyThePixelsRenderShades) {
  for (const Scene& scene : {tessellated_sphere_scene(8, 6), tessellated_sphere_scene(64, 32)}) {
    const SurfaceBuffer surface = surface_of(scene);
    const Framebuffer image = rendered(scene, "lambert", surface_lambert);
    EXPECT_EQ(surface.width, image.width);
    EXPECT_EQ(surface.height, image.height);
    EXPECT_EQ(surface.coverage, image.coverage);
  }
}

TEST(Surface, ErrorsAreRendersErrors) {
  Scene scene = tessellated_sphere_scene(8, 6);
  scene.mesh.indices.push_back(0);
  const auto surface = render_surface(scene);
  ASSERT_FALSE(surface);
  EXPECT_NE(surface.error().find("multiple of 3"), std::string::npos);
}

TEST(Surface, UnitVectorsAndNormalLengthBelowOneOnACoarseSphere) {
  const SurfaceBuffer surface = surface_of(tessellated_sphere_scene(8, 6));
  double shortest = 1;
  for (size_t pixel = 0; pixel < surface.samples.size(); ++pixel) {
    if (!surface.coverage[pixel]) continue;
    const SurfaceSample& sample = surface.samples[pixel];
    EXPECT_NEAR(glm::length(sample.to_light), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(sample.to_eye), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(sample.position), 1.0, 0.15);  // on the coarse sphere: its chords dip to ~0.9
    EXPECT_LE(glm::length(sample.normal), 1.0 + 1e-12);
    shortest = std::min(shortest, glm::length(sample.normal));
  }
  EXPECT_LT(shortest, 0.95);
}

TEST(Surface, NDotLReproducesLambertPixelByPixel) {
  for (SceneLight light : {SceneLight::model_default, SceneLight::point}) {
    Scene scene = tessellated_sphere_scene(16, 12);
    scene.light = light;
    expect_pixels(rendered(scene, "lambert", surface_lambert), surface_of(scene),
                  [](const SurfaceSample& s) { return surface_diffuse * std::max(0.0, n_dot_l(s)); });
  }
}

TEST(Perturbation, NoneIsRendersOwnImage) {
  const Scene scene = tessellated_sphere_scene(16, 12);
  const auto plain = render(scene, "phong", Mode::per_pixel, phong);
  ASSERT_TRUE(plain);
  const Framebuffer unperturbed = rendered(scene, "phong", phong, Perturbation{});
  EXPECT_EQ(plain->rgba, unperturbed.rgba);
  EXPECT_EQ(plain->coverage, unperturbed.coverage);
}

TEST(Perturbation, NegatedLightLightsTheOtherSide) {
  for (SceneLight light : {SceneLight::model_default, SceneLight::point}) {
    Scene scene = tessellated_sphere_scene(16, 12);
    scene.light = light;
    expect_pixels(rendered(scene, "lambert", surface_lambert, {.negate_light = true}), surface_of(scene),
                  [](const SurfaceSample& s) { return surface_diffuse * std::max(0.0, -n_dot_l(s)); });
  }
}

// point_attenuated: the light reflected through P keeps its distance, so only the cosine
// changes sign: diffuse sat(-N·Lp) / (0.04 d).
TEST(Perturbation, NegatedPointLightKeepsItsDistance) {
  Scene scene = tessellated_sphere_scene(16, 12);
  scene.light = SceneLight::point;  // the L render_surface reports for a point-light model
  const Params params{{"diffuse", {0.9, 0.6, 0.3}}, {"light_color", {1, 1, 1}}, {"attenuation", {0, 0.04, 0}}};
  expect_pixels(rendered(scene, "point_attenuated", params, {.negate_light = true}), surface_of(scene),
                [&](const SurfaceSample& s) {
                  const double distance = glm::length(glm::dvec3(-3, 2, -2) - s.position);
                  return surface_diffuse * std::max(0.0, -n_dot_l(s)) / (0.04 * distance);
                });
}

TEST(Perturbation, UnnormalisedNormalScalesLambertByTheNormalsLength) {
  const Scene scene = tessellated_sphere_scene(8, 6);
  expect_pixels(rendered(scene, "lambert", surface_lambert, {.unnormalised_normal = true}), surface_of(scene),
                [](const SurfaceSample& s) { return surface_diffuse * std::max(0.0, glm::dot(s.normal, s.to_light)); });
  // And it does change the image (|n| < 1 inside the triangles), unlike per vertex.
  EXPECT_NE(rendered(scene, "lambert", surface_lambert, {.unnormalised_normal = true}).rgba,
            rendered(scene, "lambert", surface_lambert).rgba);
  EXPECT_EQ(rendered(scene, "lambert", surface_lambert, {.unnormalised_normal = true}, Mode::per_vertex).rgba,
            rendered(scene, "lambert", surface_lambert, {}, Mode::per_vertex).rgba);
}

TEST(Perturbation, NegatedEyeChangesPhongButNotLambert) {
  const Scene scene = tessellated_sphere_scene(16, 12);
  EXPECT_EQ(rendered(scene, "lambert", surface_lambert, {.negate_eye = true}).rgba, rendered(scene, "lambert", surface_lambert).rgba);
  const Framebuffer plain = rendered(scene, "phong", phong);
  const Framebuffer negated = rendered(scene, "phong", phong, {.negate_eye = true});
  EXPECT_NE(plain.rgba, negated.rgba);
  // The specular lobe follows R·(-V): the phong render minus its diffuse part.
  const SurfaceBuffer surface = surface_of(scene);
  expect_pixels(negated, surface, [](const SurfaceSample& s) {
    const glm::dvec3 n = glm::normalize(s.normal);
    const glm::dvec3 r = glm::normalize(2.0 * n * glm::dot(n, s.to_light) - s.to_light);
    return surface_diffuse * std::max(0.0, n_dot_l(s)) + glm::dvec3(std::pow(std::max(0.0, glm::dot(r, -s.to_eye)), 7.0));
  }, 1e-9);
}

TEST(Perturbation, NegatedLightAlsoAppliesPerVertex) {
  const Scene scene = tessellated_sphere_scene(16, 12);
  EXPECT_NE(rendered(scene, "lambert", surface_lambert, {.negate_light = true}, Mode::per_vertex).rgba,
            rendered(scene, "lambert", surface_lambert, {}, Mode::per_vertex).rgba);
}

// Calls expected(corners, weights, interpolated normal) at every covered pixel, from the
// rasteriser's own triangles and perspective-correct weights, and compares the image.
template <typename Expected>
void expect_triangle_pixels(const Framebuffer& image, const Scene& scene, Expected expected, double tolerance = 1e-12) {
  auto visibility = rasterise_scene(scene);
  ASSERT_TRUE(visibility) << visibility.error();
  size_t covered = 0;
  for (size_t pixel = 0; pixel < visibility->samples.size(); ++pixel) {
    const VisibleSample& sample = visibility->samples[pixel];
    ASSERT_EQ(sample.covered(), image.coverage[pixel] != 0) << "pixel " << pixel;
    if (!sample.covered()) continue;
    ++covered;
    std::array<glm::dvec3, 3> corners;
    glm::dvec3 normal(0.0);
    for (int i = 0; i < 3; ++i) {
      const Vertex& v = scene.mesh.vertices[scene.mesh.indices[size_t(sample.triangle) * 3 + i]];
      corners[i] = v.position;
      normal += sample.weights[i] * v.normal;
    }
    const glm::dvec3 colour = expected(corners, sample.weights, normal);
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(image.rgba[pixel * 4 + c], colour[c], tolerance) << "pixel " << pixel;
  }
  EXPECT_GT(covered, 1000u);
}

// A point light's L built at the three corners, unit there, interpolated and not
// renormalised: Lambert sees D·max(0, N·ΣwᵢLᵢ), with |ΣwᵢLᵢ| < 1 inside a triangle.
TEST(Perturbation, InterpolatedLightEyeInterpolatesThePointLightsUnitVectors) {
  Scene scene = tessellated_sphere_scene(8, 6);
  scene.light = SceneLight::point;
  const Framebuffer image = rendered(scene, "lambert", surface_lambert, {.interpolated_light_eye = true});
  expect_triangle_pixels(image, scene, [&](const std::array<glm::dvec3, 3>& corners, const glm::dvec3& w, const glm::dvec3& n) {
    glm::dvec3 to_light(0.0);
    for (int i = 0; i < 3; ++i) to_light += w[i] * glm::normalize(scene.lights.position - corners[i]);
    return surface_diffuse * std::max(0.0, glm::dot(glm::normalize(n), to_light));
  });
  EXPECT_NE(image.rgba, rendered(scene, "lambert", surface_lambert).rgba);
}

// V likewise; a directional light's L is the same at every corner, so Lambert under it
// does not change, and nothing changes per vertex.
TEST(Perturbation, InterpolatedLightEyeInterpolatesTheEyeVector) {
  const Scene scene = tessellated_sphere_scene(8, 6);
  const Framebuffer image = rendered(scene, "phong", phong, {.interpolated_light_eye = true});
  expect_triangle_pixels(image, scene, [&](const std::array<glm::dvec3, 3>& corners, const glm::dvec3& w, const glm::dvec3& normal) {
    glm::dvec3 to_eye(0.0);
    for (int i = 0; i < 3; ++i) to_eye += w[i] * glm::normalize(scene.camera.eye - corners[i]);
    const glm::dvec3 n = glm::normalize(normal), l = scene.lights.direction;
    const glm::dvec3 r = glm::normalize(2.0 * n * glm::dot(n, l) - l);
    return surface_diffuse * std::max(0.0, glm::dot(n, l)) + glm::dvec3(std::pow(std::max(0.0, glm::dot(r, to_eye)), 7.0));
  }, 1e-9);
  EXPECT_NE(image.rgba, rendered(scene, "phong", phong).rgba);
  const Framebuffer lambert = rendered(scene, "lambert", surface_lambert, {.interpolated_light_eye = true});
  const Framebuffer plain = rendered(scene, "lambert", surface_lambert);
  for (size_t i = 0; i < plain.rgba.size(); ++i) ASSERT_NEAR(lambert.rgba[i], plain.rgba[i], 1e-12) << i;
  EXPECT_EQ(rendered(scene, "phong", phong, {.interpolated_light_eye = true}, Mode::per_vertex).rgba,
            rendered(scene, "phong", phong, {}, Mode::per_vertex).rgba);
}

// The facet's own normal, on the side the vertex normals face: one colour per triangle.
TEST(Perturbation, FacetedNormalShadesEachTriangleWithItsGeometricNormal) {
  const Scene scene = tessellated_sphere_scene(8, 6);
  const Framebuffer image = rendered(scene, "lambert", surface_lambert, {.faceted_normal = true});
  expect_triangle_pixels(image, scene, [&](const std::array<glm::dvec3, 3>& p, const glm::dvec3&, const glm::dvec3& normal) {
    glm::dvec3 facet = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    if (glm::dot(facet, normal) < 0) facet = -facet;
    return surface_diffuse * std::max(0.0, glm::dot(facet, scene.lights.direction));
  });
  EXPECT_NE(image.rgba, rendered(scene, "lambert", surface_lambert).rgba);
  EXPECT_EQ(rendered(scene, "lambert", surface_lambert, {.faceted_normal = true}, Mode::per_vertex).rgba,
            rendered(scene, "lambert", surface_lambert, {}, Mode::per_vertex).rgba);
}

}  // namespace
}  // namespace reference
