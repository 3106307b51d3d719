// The reference's camera matrices and the move of lights and eye into object space.
#include <gtest/gtest.h>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

#include "reference/ObjectSpace.h"
#include "reference/Rasteriser.h"
#include "reference/Reference.h"

namespace reference {
namespace {

void expect_matrix(const glm::dmat4& actual, const glm::dmat4& expected) {
  for (int column = 0; column < 4; ++column) {
    for (int row = 0; row < 4; ++row) {
      EXPECT_NEAR(actual[column][row], expected[column][row], 1e-12) << "[" << column << "][" << row << "]";
    }
  }
}

void expect_vector(const glm::dvec3& actual, const glm::dvec3& expected) {
  EXPECT_NEAR(actual.x, expected.x, 1e-12);
  EXPECT_NEAR(actual.y, expected.y, 1e-12);
  EXPECT_NEAR(actual.z, expected.z, 1e-12);
}

// Written out independently; glm's left-handed [0, 1] versions must agree.
TEST(Matrices, AgreeWithGlmLeftHandedZeroToOne) {
  const Camera camera;
  expect_matrix(view_matrix(camera), glm::lookAtLH(camera.eye, camera.target, camera.up));
  expect_matrix(
      projection_matrix(camera, 4.0 / 3.0),
      glm::perspectiveLH_ZO(glm::radians(camera.fovy_degrees), 4.0 / 3.0, camera.near_plane, camera.far_plane));
}

TEST(Matrices, TargetAtImageCentreUpIsRowZeroDepthRangeIsZeroToOne) {
  const Camera camera;  // eye (-100, 50, 0), looking at the origin, +y up
  const glm::dmat4 world_to_clip = projection_matrix(camera, 1.0) * view_matrix(camera);
  const auto window = [&](const glm::dvec3& p) { return window_position(world_to_clip * glm::dvec4(p, 1), 256, 256); };
  const glm::dvec3 target = window(camera.target);
  EXPECT_NEAR(target.x, 128, 1e-9);
  EXPECT_NEAR(target.y, 128, 1e-9);
  EXPECT_LT(window({0, 10, 0}).y, 128) << "world up appears toward row 0";
  // Left-handed: with the eye at -x looking toward +x, world +z is on the left.
  EXPECT_LT(window({0, 0, 10}).x, 128);

  const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
  EXPECT_NEAR(window(camera.eye + camera.near_plane * forward).z, 0.0, 1e-12);
  EXPECT_NEAR(window(camera.eye + camera.far_plane * forward).z, 1.0, 1e-12);
}

TEST(ObjectSpace, LightAndEyeGoThroughTheInverseWorldMatrix) {
  // Object +x maps to world +y, then the object moves to (10, 20, 30).
  const glm::dmat4 world =
      glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(10, 20, 30)), glm::radians(90.0), glm::dvec3(0, 0, 1));
  Lights lights;  // direction (0, 1, 0), position (0, 50, 0)
  Camera camera;  // eye (-100, 50, 0)
  const ObjectSpaceLighting object = to_object_space(lights, camera, world);
  expect_vector(object.light_direction, {1, 0, 0});
  // Positions keep the translation (w = 1): the book's w = 0 would give (50, 0, 0).
  expect_vector(object.light_position, {30, 10, -30});
  expect_vector(object.eye_position, {30, 110, -30});
}

TEST(ObjectSpace, LightDirectionIsRenormalisedUnderScale) {
  const glm::dmat4 world = glm::scale(glm::dmat4(1.0), glm::dvec3(2, 4, 8));
  Lights lights;
  lights.direction = glm::normalize(glm::dvec3(1, 1, 0));
  const ObjectSpaceLighting object = to_object_space(lights, Camera{}, world);
  expect_vector(object.light_direction, glm::normalize(glm::dvec3(0.5, 0.25, 0)));
  expect_vector(object.light_position, {0, 12.5, 0});
}

}  // namespace
}  // namespace reference
