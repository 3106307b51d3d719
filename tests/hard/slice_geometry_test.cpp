// Slice geometry: every pixel's configuration has the angles the slice claims for it.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "hard/Slice.h"

namespace shaderbed::hard {
namespace {

constexpr double pi = std::numbers::pi;

double angle(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

const SliceSpec kPerpendicular{.to_light = glm::normalize(glm::dvec3(1, 2, 0)), .to_eye = glm::normalize(glm::dvec3(-2, 1, 0))};

TEST(SliceGeometry, SizeIsOddAndOneQuadPerPixel) {
  const Slice s = make_slice(kPerpendicular, 32);
  EXPECT_EQ(s.width, 33);
  EXPECT_EQ(s.height, 33);
  EXPECT_EQ(s.mesh.vertices.size(), 33u * 33u * 4u);
  EXPECT_EQ(s.mesh.triangle_count(), 33u * 33u * 2u);
}

TEST(SliceGeometry, SpherePixelsHaveTheirPolarAngleAndAzimuth) {
  const Slice s = make_slice(kPerpendicular, 33);
  const glm::dvec3 v = kPerpendicular.to_eye, l = kPerpendicular.to_light;
  for (int y = 0; y < s.height; y += 4)
    for (int x = 0; x < s.width; x += 4) {
      const SlicePixel& p = s.pixels[size_t(y) * s.width + x];
      const reference::Configuration c = pixel_configuration(s, p, false);
      const glm::dvec3 n = glm::normalize(c.normal);
      EXPECT_NEAR(p.polar, pi * y / (s.height - 1), 1e-12);
      // The normal the GPU gets (float) is within float rounding of the claimed angle.
      EXPECT_NEAR(angle(n, v), p.polar, 1e-6) << x << "," << y;
      // V seen from the pixel is the slice's V to ~2e-7 rad: the eye is far, the grid tiny.
      EXPECT_LT(angle(glm::normalize(c.to_eye), v), 1e-6);
      EXPECT_LT(angle(glm::normalize(c.to_light), l), 1e-6);
      // Azimuth about V, 0 on L's side: here L is perpendicular to V, so N.L = sin(polar) cos(azimuth).
      EXPECT_NEAR(glm::dot(n, l), std::sin(p.polar) * std::cos(p.azimuth), 1e-6) << x << "," << y;
      EXPECT_NEAR(glm::dot(glm::dvec3(p.tangent), n), 0.0, 1e-6);
    }
}

TEST(SliceGeometry, SphereHitsTheSpecialConfigurationsExactly) {
  const Slice s = make_slice(kPerpendicular, 129);
  const glm::dvec3 v = kPerpendicular.to_eye, l = kPerpendicular.to_light;
  const glm::dvec3 h = glm::normalize(l + v);
  auto normal = [&](int x, int y) { return glm::normalize(glm::dvec3(s.pixels[size_t(y) * s.width + x].normal)); };
  const int centre = s.width / 2;
  EXPECT_NEAR(angle(normal(centre, 0), v), 0, 1e-7);                  // N = V
  EXPECT_NEAR(angle(normal(centre, s.height - 1), -v), 0, 1e-7);      // N = -V
  EXPECT_NEAR(angle(normal(centre, (s.height - 1) / 2), l), 0, 1e-7); // N = L, N.V = 0
  EXPECT_NEAR(angle(normal(centre, (s.height - 1) / 4), h), 0, 1e-7); // N = H
  EXPECT_NEAR(glm::dot(normal(0, (s.height - 1) / 4), h), 0, 1e-7);      // N.H = 0 (azimuth -pi, polar pi/4)
}

TEST(SliceGeometry, LobeCentreIsTheHalfVectorAndEdgesAtTheRadius) {
  SliceSpec spec = kPerpendicular;
  spec.layout = NormalLayout::lobe;
  spec.lobe_radius = 0.005;
  const Slice s = make_slice(spec, 65);
  const glm::dvec3 h = glm::normalize(spec.to_light + spec.to_eye);
  const int c = s.width / 2;
  EXPECT_NEAR(angle(s.pixels[size_t(c) * s.width + c].claimed_normal, h), 0, 1e-12);
  EXPECT_NEAR(angle(s.pixels[size_t(c) * s.width + 0].claimed_normal, h), 0.005, 1e-12);
  EXPECT_NEAR(angle(s.pixels[size_t(0) * s.width + c].claimed_normal, h), 0.005, 1e-12);
}

TEST(SliceGeometry, PlaneLightDistanceRunsFromTheHeight) {
  SliceSpec spec{.layout = NormalLayout::plane, .plane_normal = glm::dvec3(0, 1, 0), .light_height = 1e-6};
  const Slice s = make_slice(spec, 33);
  const int c = s.width / 2;
  const reference::Configuration centre = pixel_configuration(s, s.pixels[size_t(c) * s.width + c], true);
  EXPECT_NEAR(centre.distance, 1e-6, 1e-12);
  EXPECT_NEAR(angle(glm::normalize(centre.to_light), glm::dvec3(0, 1, 0)), 0, 1e-6);
  const reference::Configuration corner = pixel_configuration(s, s.pixels[0], true);
  EXPECT_GT(corner.distance, kGridHalfSize);   // the corner pixel centre is ~1.4 half-widths out
  EXPECT_LT(corner.distance, 1.5 * kGridHalfSize);
}

TEST(SliceGeometry, LongNormalsAreLongerByTheirEpsilon) {
  SliceSpec spec = kPerpendicular;
  spec.long_normals = true;
  const Slice s = make_slice(spec, 9);
  for (int i = 0; i < 3; ++i) {
    const double eps = std::pow(10.0, -6 + i);
    EXPECT_NEAR(glm::length(glm::dvec3(s.pixels[size_t(i)].normal)), 1 + eps, 1e-7) << i;
  }
}

TEST(SliceGeometry, HalfAngleMapTurnsNAwayFromHAndSetsARowParameter) {
  SliceSpec spec = kPerpendicular;
  spec.layout = NormalLayout::half_angle;
  spec.row_param = "slope_m";
  spec.row_first = 1;
  spec.row_last = 1e-3;
  const Slice s = make_slice(spec, 33);
  const glm::dvec3 l = glm::normalize(spec.to_light), v = glm::normalize(spec.to_eye), h = glm::normalize(l + v);
  ASSERT_EQ(s.row_values.size(), 33u);
  EXPECT_DOUBLE_EQ(s.row_values.front(), 1);
  EXPECT_NEAR(s.row_values.back(), 1e-3, 1e-15);
  EXPECT_NEAR(s.row_values[16], std::sqrt(1e-3), 1e-12);   // log-spaced: the middle row is the geometric mean
  for (int x = 0; x < s.width; x += 4) {
    const SlicePixel& p = s.pixels[size_t(7) * s.width + x];
    EXPECT_NEAR(p.half_angle, kMinHalfAngle * std::pow(kMaxHalfAngle / kMinHalfAngle, x / 32.0), 1e-12);
    EXPECT_NEAR(angle(p.claimed_normal, h), p.half_angle, 1e-9) << x;
    EXPECT_NEAR(glm::dot(p.claimed_normal, l), glm::dot(p.claimed_normal, v), 1e-12) << x;   // across the L-V plane
    EXPECT_GT(glm::dot(p.claimed_normal, l), 0.0) << x;
  }
  // Each row's parameters carry its value in every component; the mesh of a row is its quads.
  const auto params = row_params(s, 32, {{"slope_m", {0.5}}, {"roughness_xy", {0.2, 0.3}}});
  EXPECT_NEAR(params.at("slope_m")[0], 1e-3, 1e-15);
  EXPECT_EQ(params.at("roughness_xy"), (std::vector<double>{0.2, 0.3}));
  const Mesh row = row_mesh(s, 5);
  ASSERT_EQ(row.vertices.size(), 33u * 4u);
  EXPECT_EQ(row.vertices.front().position, s.mesh.vertices[5 * 33 * 4].position);
  EXPECT_EQ(*std::max_element(row.indices.begin(), row.indices.end()), 33u * 4u - 1u);
}

}  // namespace
}  // namespace shaderbed::hard
