// Every scene quantity a case can bind, checked against matrices built here by hand from
// the camera (D3DXMatrixLookAtLH, D3DXMatrixPerspectiveFovLH with depth in [0, 1]) and a
// world matrix that rotates, scales unevenly and translates, so that no transpose,
// inverse or normal-matrix mix-up can pass.
#include <cmath>
#include <numbers>
#include <utility>
#include <string>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/Scene.h"

namespace shaderbed {
namespace {

SceneSetup test_scene() {
  SceneSetup s;
  s.width = 64;
  s.height = 48;   // aspect 4:3, so x and y scales differ
  s.world = glm::translate(glm::dmat4(1.0), glm::dvec3(3, -2, 5)) *
            glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1, 2, -0.5))) *
            glm::scale(glm::dmat4(1.0), glm::dvec3(1.5, 0.5, 2.0));
  s.lights.ambient = {0.1, 0.2, 0.3};
  return s;
}

// D3DXMatrixLookAtLH as column-vector M (clip = M v): rows are the camera's axes.
glm::dmat4 view_by_hand(const Camera& c) {
  const glm::dvec3 z = glm::normalize(c.target - c.eye);
  const glm::dvec3 x = glm::normalize(glm::cross(c.up, z));
  const glm::dvec3 y = glm::cross(z, x);
  glm::dmat4 m(1.0);
  for (int i = 0; i < 3; ++i) {
    m[i][0] = x[i];
    m[i][1] = y[i];
    m[i][2] = z[i];
  }
  m[3] = glm::dvec4(-glm::dot(x, c.eye), -glm::dot(y, c.eye), -glm::dot(z, c.eye), 1.0);
  return m;
}

// D3DXMatrixPerspectiveFovLH: depth zn -> 0, zf -> 1, w = view z.
glm::dmat4 projection_by_hand(const Camera& c, double aspect) {
  const double y_scale = 1.0 / std::tan(c.fovy_degrees * std::numbers::pi / 360.0);
  glm::dmat4 m(0.0);
  m[0][0] = y_scale / aspect;
  m[1][1] = y_scale;
  m[2][2] = c.far_plane / (c.far_plane - c.near_plane);
  m[2][3] = 1.0;
  m[3][2] = -c.near_plane * c.far_plane / (c.far_plane - c.near_plane);
  return m;
}

glm::dmat4 mat4_of(const NamedValues& q, const std::string& name) {
  const auto& v = q.at(name);
  EXPECT_EQ(v.size(), 16u) << name;
  glm::dmat4 m(0.0);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[c][r] = v.at(size_t(c) * 4 + r);
  return m;
}

glm::dmat3 mat3_of(const NamedValues& q, const std::string& name) {
  const auto& v = q.at(name);
  EXPECT_EQ(v.size(), 9u) << name;
  glm::dmat3 m(0.0);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) m[c][r] = v.at(size_t(c) * 3 + r);
  return m;
}

glm::dvec4 vec4_of(const NamedValues& q, const std::string& name) {
  const auto& v = q.at(name);
  EXPECT_EQ(v.size(), 4u) << name;
  return {v.at(0), v.at(1), v.at(2), v.at(3)};
}

// Relative to the matrix's size: the values are floats.
template <typename M>
void expect_matrix_near(const M& got, const M& want, const std::string& what) {
  double scale = 0, worst = 0;
  for (int c = 0; c < M::length(); ++c)
    for (int r = 0; r < M::col_type::length(); ++r) {
      scale = std::max(scale, std::abs(want[c][r]));
      worst = std::max(worst, std::abs(got[c][r] - want[c][r]));
    }
  EXPECT_LE(worst, 1e-6 * std::max(scale, 1.0)) << what;
}

void expect_vec_near(const glm::dvec4& got, const glm::dvec4& want, const std::string& what, double tol = 1e-5) {
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(got[i], want[i], tol * std::max(1.0, std::abs(want[i]))) << what << "[" << i << "]";
}

TEST(SceneQuantities, MatricesMatchTheD3dxConventionsBuiltByHand) {
  const SceneSetup s = test_scene();
  const NamedValues q = scene_quantities(s);
  const glm::dmat4 view = view_by_hand(s.camera);
  const glm::dmat4 projection = projection_by_hand(s.camera, 64.0 / 48.0);
  expect_matrix_near(mat4_of(q, "world"), s.world, "world");
  expect_matrix_near(mat4_of(q, "view"), view, "view");
  expect_matrix_near(mat4_of(q, "projection"), projection, "projection");
  expect_matrix_near(mat4_of(q, "world_view"), view * s.world, "world_view");
  expect_matrix_near(mat4_of(q, "view_projection"), projection * view, "view_projection");
  expect_matrix_near(mat4_of(q, "transform"), projection * view * s.world, "transform");
}

TEST(SceneQuantities, ProductsAgreeWithEachOther) {
  const NamedValues q = scene_quantities(test_scene());
  // world_view . projection == transform, in clip = M v order: P (V W).
  expect_matrix_near(mat4_of(q, "projection") * mat4_of(q, "world_view"), mat4_of(q, "transform"), "P * WV");
  expect_matrix_near(mat4_of(q, "view_projection") * mat4_of(q, "world"), mat4_of(q, "transform"), "VP * W");
}

TEST(SceneQuantities, EverySuffixIsTheInverseTransposeOrBoth) {
  const SceneSetup s = test_scene();
  const NamedValues q = scene_quantities(s);
  const glm::dmat4 view = view_by_hand(s.camera);
  const glm::dmat4 projection = projection_by_hand(s.camera, 64.0 / 48.0);
  const std::pair<const char*, glm::dmat4> exact[] = {{"world", s.world},
                                                      {"view", view},
                                                      {"projection", projection},
                                                      {"world_view", view * s.world},
                                                      {"view_projection", projection * view},
                                                      {"transform", projection * view * s.world}};
  for (const auto& [name, m] : exact) {
    const std::string n = name;
    // Against the double-precision inverse: a product of the float matrices would measure
    // the float rounding amplified by the matrices' condition, not the quantity.
    expect_matrix_near(mat4_of(q, n + "_inverse"), glm::inverse(m), n + "_inverse");
    expect_matrix_near(mat4_of(q, n + "_transpose"), glm::transpose(m), n + "_transpose");
    expect_matrix_near(mat4_of(q, n + "_inverse_transpose"), glm::transpose(glm::inverse(m)), n + "_inverse_transpose");
  }
}

TEST(SceneQuantities, NormalMatricesKeepNormalsPerpendicularToTheSurface) {
  const SceneSetup s = test_scene();
  const NamedValues q = scene_quantities(s);
  // A surface through the origin spanned by two tangents; its normal is their cross product.
  const glm::dvec3 t1 = glm::normalize(glm::dvec3(1, 0.3, -0.2)), t2 = glm::normalize(glm::dvec3(-0.4, 1, 0.6));
  const glm::dvec3 n = glm::cross(t1, t2);
  const glm::dmat4 world_view = view_by_hand(s.camera) * s.world;
  for (const auto& [name, to] : {std::pair{"normal_matrix", s.world}, std::pair{"normal_matrix_view", world_view}}) {
    const glm::dvec3 transformed = mat3_of(q, name) * n;
    // Perpendicular to both transformed tangents, and on the same side as their cross product.
    const glm::dvec3 a = glm::dvec3(to * glm::dvec4(t1, 0)), b = glm::dvec3(to * glm::dvec4(t2, 0));
    EXPECT_NEAR(glm::dot(glm::normalize(transformed), glm::normalize(a)), 0.0, 1e-6) << name;
    EXPECT_NEAR(glm::dot(glm::normalize(transformed), glm::normalize(b)), 0.0, 1e-6) << name;
    EXPECT_NEAR(glm::dot(glm::normalize(transformed), glm::normalize(glm::cross(a, b))), 1.0, 1e-6) << name;
  }
}

TEST(SceneQuantities, LightsAndEyeInEverySpace) {
  const SceneSetup s = test_scene();
  const NamedValues q = scene_quantities(s);
  const glm::dmat4 view = view_by_hand(s.camera);
  const glm::dmat4 object_from_world = glm::inverse(s.world);
  const glm::dvec3 light{0, 50, 0}, eye{-100, 50, 0}, toward{0, 1, 0};
  // World: as the scene states them.
  expect_vec_near(vec4_of(q, "light_position_world"), {light, 1}, "light_position_world");
  expect_vec_near(vec4_of(q, "eye_position_world"), {eye, 1}, "eye_position_world");
  expect_vec_near(vec4_of(q, "light_vector_world"), {toward, 0}, "light_vector_world");
  // View: the eye sits at the origin; the point light straight above the target.
  expect_vec_near(vec4_of(q, "eye_position_view"), {0, 0, 0, 1}, "eye_position_view", 1e-4);
  expect_vec_near(vec4_of(q, "light_position_view"), view * glm::dvec4(light, 1), "light_position_view");
  expect_vec_near(vec4_of(q, "light_vector_view"), {glm::normalize(glm::dvec3(view * glm::dvec4(toward, 0))), 0},
                  "light_vector_view");
  // Object: through the inverse world matrix, positions with w = 1, the direction renormalised.
  expect_vec_near(vec4_of(q, "light_position"), object_from_world * glm::dvec4(light, 1), "light_position");
  expect_vec_near(vec4_of(q, "eye_position"), object_from_world * glm::dvec4(eye, 1), "eye_position");
  expect_vec_near(vec4_of(q, "light_vector"),
                  {glm::normalize(glm::dvec3(object_from_world * glm::dvec4(toward, 0))), 0}, "light_vector");
  expect_vec_near(vec4_of(q, "ambient_light"), {0.1, 0.2, 0.3, 1}, "ambient_light");
}

TEST(SceneQuantities, ClipSpaceOfTheTargetIsTheImageCentre) {
  // The camera looks at the origin: the transform puts it at NDC (0, 0), depth in (0, 1).
  const NamedValues q = scene_quantities(SceneSetup{});
  const glm::dvec4 clip = mat4_of(q, "transform") * glm::dvec4(0, 0, 0, 1);
  EXPECT_NEAR(clip.x / clip.w, 0, 1e-6);
  EXPECT_NEAR(clip.y / clip.w, 0, 1e-6);
  EXPECT_GT(clip.z / clip.w, 0);
  EXPECT_LT(clip.z / clip.w, 1);
}

}  // namespace
}  // namespace shaderbed
