// Ward isotropic and anisotropic (docs/models.md, errata E2-E4) at hand-computed
// configurations in the local frame of evaluate() (N = +z, T = +x), and the tangent that
// reaches the model in renders.
#include <gtest/gtest.h>

#include <cmath>

#include "ModelTestSupport.h"
#include "PixelRays.h"

namespace reference {
namespace {

using namespace testing;

const glm::dvec3 ward_diffuse{0.1, 0.2, 0.3};
const glm::dvec3 ward_specular{0.5, 0.6, 0.7};
const double cos30 = std::sqrt(3.0) / 2;

// ---- ward_iso: (D + S exp(-tan²g/s²)/(4 pi s²)/sqrt((N·L)(N·V))) sat(N·L) ---------------

const double sigma = 0.25;
const Params ward_iso{{"diffuse", to_param(ward_diffuse)}, {"specular", to_param(ward_specular)}, {"roughness", {sigma}}};
const double iso_peak = 1 / (4 * pi * sigma * sigma);  // 4 pi, not the isotropic shader's 2 pi (E2)

TEST(WardIsotropic, EverythingAlongTheNormalIsDiffusePlusThePeak) {
  expect_colour_near(eval("ward_iso", ward_iso, z_axis, z_axis), ward_diffuse + iso_peak * ward_specular);
  EXPECT_NEAR(iso_peak, 1.2732395447351628, 1e-15);  // 1 / (pi / 4)
}

TEST(WardIsotropic, MirrorDirectionHasHEqualToN) {
  // L, V at 60 degrees on opposite sides: tan(gamma) = 0, sqrt((N·L)(N·V)) = 1/2.
  expect_colour_near(eval("ward_iso", ward_iso, direction(60, 0), direction(60, 180)),
                     0.5 * (ward_diffuse + 2 * iso_peak * ward_specular));
}

TEST(WardIsotropic, OffSpecularGaussianInTanGamma) {
  // L at 60 degrees, V = N: H at gamma = 30 degrees, tan² = 1/3; sqrt((N·L)(N·V)) = sqrt(1/2).
  const double lobe = std::exp(-(1.0 / 3) / (sigma * sigma)) * iso_peak / std::sqrt(0.5);
  expect_colour_near(eval("ward_iso", ward_iso, direction(60), z_axis), 0.5 * (ward_diffuse + lobe * ward_specular));
}

TEST(WardIsotropic, SpecularNeedsBothLightAndEyeAboveTheSurface) {
  // E4: the eye below the horizon leaves the diffuse term; no NaN from sqrt of a negative.
  expect_colour_near(eval("ward_iso", ward_iso, direction(30), direction(100)), cos30 * ward_diffuse);
  // Grazing eye (N·V = 0 exactly): the gate is strict, no division by zero.
  expect_colour_near(eval("ward_iso", ward_iso, direction(30, 0), x_axis), cos30 * ward_diffuse);
  expect_colour_near(eval("ward_iso", ward_iso, direction(100), direction(30)), glm::dvec3(0.0));
  expect_colour_near(eval("ward_iso", ward_iso, direction(100), direction(100)), glm::dvec3(0.0));
}

TEST(WardIsotropic, RoughnessMustBePositive) {
  const auto zero = make_model("ward_iso", {{"diffuse", grey(1)}, {"specular", grey(1)}, {"roughness", {0}}});
  ASSERT_FALSE(zero);
  EXPECT_EQ(zero.error(), "ward_iso: parameter 'roughness' must be > 0 (sigma divides)");
}

// ---- ward_aniso: frame X = normalize(T - N(N·T)), Y = N x X (E3) ------------------------

const glm::dvec2 sigma_xy{0.9, 0.1};
const Params ward_aniso{
    {"diffuse", to_param(ward_diffuse)}, {"specular", to_param(ward_specular)}, {"roughness_xy", {0.9, 0.1}}};
const double aniso_peak = 1 / (4 * pi * sigma_xy.x * sigma_xy.y);

// The lobe for H at angle gamma from N in the tangent direction that makes angle phi with
// X: H·X = sin(gamma) cos(phi), H·Y = sin(gamma) sin(phi), N·H = cos(gamma).
double aniso_lobe(double gamma_degrees, double phi_degrees) {
  const double g = glm::radians(gamma_degrees), p = glm::radians(phi_degrees);
  const double hx = std::sin(g) * std::cos(p) / sigma_xy.x, hy = std::sin(g) * std::sin(p) / sigma_xy.y;
  return std::exp(-2 * (hx * hx + hy * hy) / (1 + std::cos(g)));
}

TEST(WardAnisotropic, EverythingAlongTheNormalIsDiffusePlusThePeak) {
  expect_colour_near(eval("ward_aniso", ward_aniso, z_axis, z_axis), ward_diffuse + aniso_peak * ward_specular);
}

TEST(WardAnisotropic, HighlightIsWideAlongTheTangentAndNarrowAcrossIt) {
  // L at 60 degrees, V = N: H at 30 degrees, toward X (phi = 0) or toward Y (phi = 90).
  const double scale = aniso_peak / std::sqrt(0.5);
  const glm::dvec3 along = eval("ward_aniso", ward_aniso, direction(60, 0), z_axis);
  const glm::dvec3 across = eval("ward_aniso", ward_aniso, direction(60, 90), z_axis);
  expect_colour_near(along, 0.5 * (ward_diffuse + scale * aniso_lobe(30, 0) * ward_specular));
  expect_colour_near(across, 0.5 * (ward_diffuse + scale * aniso_lobe(30, 90) * ward_specular));
  expect_colour_near(eval("ward_aniso", ward_aniso, direction(60, 45), z_axis),
                     0.5 * (ward_diffuse + scale * aniso_lobe(30, 45) * ward_specular));
  EXPECT_GT(along.r - 0.5 * ward_diffuse.r, 1000 * (across.r - 0.5 * ward_diffuse.r));  // sigma_x = 9 sigma_y
}

TEST(WardAnisotropic, FrameFollowsTheTangent) {
  // Rotating T by 90 degrees about N swaps the roles of the two azimuths.
  const glm::dvec3 y_axis{0, 1, 0};
  expect_colour_near(eval("ward_aniso", ward_aniso, direction(60, 90), z_axis, z_axis, y_axis),
                     eval("ward_aniso", ward_aniso, direction(60, 0), z_axis, z_axis, x_axis));
  // A tangent at 30 degrees azimuth: H at azimuth 75 makes 45 degrees with X.
  const double scale = aniso_peak / std::sqrt(0.5);
  expect_colour_near(eval("ward_aniso", ward_aniso, direction(60, 75), z_axis, z_axis, direction(90, 30)),
                     0.5 * (ward_diffuse + scale * aniso_lobe(30, 45) * ward_specular));
}

TEST(WardAnisotropic, TangentIsOrthogonalisedAndNormalised) {
  // T - N(N·T) removes any normal component; the length does not matter. Per pixel the
  // interpolated tangent is neither unit nor orthogonal to the renormalised normal.
  Shader shader("ward_aniso", ward_aniso);
  const glm::dvec3 L = direction(50, 20), V = direction(25, 250);
  const glm::dvec3 reference_colour = shader(L, V, z_axis, x_axis);
  expect_colour_near(shader(L, V, z_axis, glm::dvec3(1, 0, 5)), reference_colour, 1e-13);
  expect_colour_near(shader(L, V, z_axis, glm::dvec3(0.01, 0, -0.3)), reference_colour, 1e-13);
  expect_colour_near(shader(L, V, z_axis, glm::dvec3(-1, 0, 0)), reference_colour, 1e-13);  // Y flips too
}

TEST(WardAnisotropic, SpecularNeedsBothLightAndEyeAboveTheSurface) {
  expect_colour_near(eval("ward_aniso", ward_aniso, direction(30), direction(100)), cos30 * ward_diffuse);
  expect_colour_near(eval("ward_aniso", ward_aniso, direction(100), direction(30)), glm::dvec3(0.0));
}

TEST(WardAnisotropic, TangentAlongTheNormalDropsTheSpecularTerm) {
  // X is undefined when T is parallel to N; docs/models.md is silent, the reference keeps
  // the diffuse term only (finite, where a GPU would give NaN).
  expect_colour_near(eval("ward_aniso", ward_aniso, z_axis, z_axis, z_axis, z_axis), ward_diffuse);
  expect_colour_near(eval("ward_aniso", ward_aniso, z_axis, z_axis, z_axis, glm::dvec3(0.0)), ward_diffuse);
}

TEST(WardAnisotropic, EqualRoughnessesMatchIsotropicWardOnlyAtThePeak) {
  // With sx = sy = s the Ch.7 form's exponent is -2 sin²g / (s² (1 + cos g)) =
  // -2 (1 - cos g) / s², the isotropic form's -tan²g / s². They agree at g = 0 and to
  // second order near it, not beyond: the book calls the forms "functionally equivalent".
  const Params round{
      {"diffuse", to_param(ward_diffuse)}, {"specular", to_param(ward_specular)}, {"roughness_xy", {sigma, sigma}}};
  expect_colour_near(eval("ward_aniso", round, direction(60, 0), direction(60, 180)),
                     eval("ward_iso", ward_iso, direction(60, 0), direction(60, 180)));
  // g = 30 degrees: exp(-2 (1 - cos30) / s²) against exp(-(1/3) / s²).
  const double scale = iso_peak / std::sqrt(0.5);
  const double aniso = 0.5 * (ward_diffuse.r + scale * std::exp(-2 * (1 - cos30) / (sigma * sigma)) * ward_specular.r);
  const double iso = 0.5 * (ward_diffuse.r + scale * std::exp(-(1.0 / 3) / (sigma * sigma)) * ward_specular.r);
  EXPECT_NEAR(eval("ward_aniso", round, direction(60), z_axis).r, aniso, 1e-12);
  EXPECT_NEAR(eval("ward_iso", ward_iso, direction(60), z_axis).r, iso, 1e-12);
  EXPECT_GT(aniso / iso, 1.05);
}

TEST(WardAnisotropic, RoughnessNeedsTwoPositiveValues) {
  const Params base{{"diffuse", grey(1)}, {"specular", grey(1)}};
  Params one = base;
  one["roughness_xy"] = {0.5};
  const auto wrong_count = make_model("ward_aniso", one);
  ASSERT_FALSE(wrong_count);
  EXPECT_EQ(wrong_count.error(), "ward_aniso: parameter 'roughness_xy' needs 2 values, got 1 value(s)");
  Params zero = base;
  zero["roughness_xy"] = {0.5, 0};
  const auto zero_error = make_model("ward_aniso", zero);
  ASSERT_FALSE(zero_error);
  EXPECT_NE(zero_error.error().find("'roughness_xy' must be > 0"), std::string::npos) << zero_error.error();
}

// ---- the tangent in renders ---------------------------------------------------------------

// One triangle with three different tangents, seen obliquely. Per pixel, the model must
// see the perspective-correctly interpolated tangent (the same weights as the position and
// normal); per vertex, each vertex's own tangent. The expected colours come from the
// model itself at the attributes interpolated with the pixel ray's barycentrics, so this
// checks the plumbing, not the equation.
class WardTangentInRenders : public ::testing::Test {
 protected:
  void SetUp() override {
    scene.width = 48;
    scene.height = 48;
    scene.camera.eye = {-20, 45, -35};
    scene.camera.target = {0, 0, 0};
    scene.lights.direction = glm::normalize(glm::dvec3(0.4, 1, -0.6));
    const std::array<glm::dvec3, 3> positions{{{-25, 0, -20}, {25, 2, -15}, {0, -2, 30}}};
    const std::array<glm::dvec3, 3> normals{{{0.1, 1, 0}, {-0.2, 1, 0.1}, {0, 1, -0.3}}};
    const std::array<glm::dvec3, 3> tangents{{{1, 0, 0}, {0, 0, 2}, {-0.7, 0.1, 0.7}}};
    for (int i = 0; i < 3; ++i) scene.mesh.vertices.push_back({positions[i], normals[i], tangents[i], {0, 0}});
    scene.mesh.indices = {0, 1, 2};
  }

  SurfacePoint interpolated(const glm::dvec3& w) const {
    const auto& v = scene.mesh.vertices;
    SurfacePoint point{};
    for (int i = 0; i < 3; ++i) {
      point.position += w[i] * v[i].position;
      point.normal += w[i] * v[i].normal;
      point.tangent += w[i] * v[i].tangent;
    }
    point.normal = glm::normalize(point.normal);
    return point;
  }

  // The barycentrics of the ray through pixel (x, y) on the triangle's plane (world =
  // object space here).
  glm::dvec3 weights_at(int x, int y) const {
    const auto& v = scene.mesh.vertices;
    const glm::dvec3 a = v[0].position, b = v[1].position, c = v[2].position;
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const glm::dmat4 world_to_clip = projection_matrix(scene.camera, 1.0) * view_matrix(scene.camera);
    const glm::dvec3 q = pixel_ray_hit(world_to_clip, scene.camera.eye, scene.width, scene.height, x, y, a, n);
    const double u = glm::dot(glm::cross(c - b, q - b), n) / glm::dot(n, n);
    const double v_weight = glm::dot(glm::cross(a - c, q - c), n) / glm::dot(n, n);
    return {u, v_weight, 1 - u - v_weight};
  }

  // Checks every covered pixel against expected(weights), and that the expected colours
  // vary over the triangle (a highlight, not a flat diffuse colour).
  template <typename Expected>
  void check(Mode mode, Expected expected) {
    const auto image = render(scene, "ward_aniso", mode, params);
    ASSERT_TRUE(image) << image.error();
    int covered = 0;
    double lowest = INFINITY, highest = -INFINITY;
    for (int y = 0; y < scene.height; ++y) {
      for (int x = 0; x < scene.width; ++x) {
        const size_t pixel = size_t(y) * scene.width + x;
        if (!image->coverage[pixel]) continue;
        ++covered;
        const glm::dvec3 colour = expected(weights_at(x, y));
        lowest = std::min(lowest, colour.r);
        highest = std::max(highest, colour.r);
        for (int k = 0; k < 3; ++k) ASSERT_NEAR(image->rgba[pixel * 4 + k], colour[k], 1e-9) << x << "," << y;
      }
    }
    EXPECT_GT(covered, 300);
    EXPECT_GT(highest - lowest, 0.1) << "the highlight should vary over the triangle";
  }

  ObjectSpaceLighting lighting() const { return {scene.lights.direction, scene.lights.position, scene.camera.eye}; }

  Scene scene;
  const Params params{{"diffuse", grey(0.2)}, {"specular", grey(1)}, {"roughness_xy", {0.6, 0.08}}};
  Shader shader{"ward_aniso", params};
};

TEST_F(WardTangentInRenders, PerPixelUsesThePerspectiveCorrectInterpolatedTangent) {
  check(Mode::per_pixel, [&](const glm::dvec3& w) { return shader.shade(interpolated(w), lighting()); });
}

TEST_F(WardTangentInRenders, PerPixelDiffersFromAFixedTangent) {
  // Guards the test above: with every tangent replaced by the first, the image changes.
  const auto with_tangents = render(scene, "ward_aniso", Mode::per_pixel, params);
  for (Vertex& vertex : scene.mesh.vertices) vertex.tangent = {1, 0, 0};
  const auto fixed = render(scene, "ward_aniso", Mode::per_pixel, params);
  ASSERT_TRUE(with_tangents && fixed);
  double largest = 0;
  for (size_t i = 0; i < fixed->rgba.size(); ++i) {
    largest = std::max(largest, std::abs(fixed->rgba[i] - with_tangents->rgba[i]));
  }
  EXPECT_GT(largest, 0.05);
}

TEST_F(WardTangentInRenders, PerVertexShadesEachVertexWithItsOwnTangent) {
  std::array<glm::dvec3, 3> vertex_colours;
  for (int i = 0; i < 3; ++i) {
    const Vertex& v = scene.mesh.vertices[i];
    vertex_colours[i] = shader.shade({v.position, glm::normalize(v.normal), v.tangent, v.uv}, lighting());
  }
  check(Mode::per_vertex, [&](const glm::dvec3& w) {
    return w[0] * vertex_colours[0] + w[1] * vertex_colours[1] + w[2] * vertex_colours[2];
  });
}

}  // namespace
}  // namespace reference
