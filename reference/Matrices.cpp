// The reference's own camera matrices, written out from the D3DX formulas rather than
// taken from glm, so the harness can check its matrices against an independent copy.
// glm convention: column vectors, m[column][row]; D3DX's row-vector matrices transposed.
#include <cmath>
#include <numbers>

#include "reference/Reference.h"

namespace reference {

// D3DXMatrixLookAtLH: +z looks from the eye toward the target, +x is up × forward.
glm::dmat4 view_matrix(const Camera& camera) {
  const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
  const glm::dvec3 right = glm::normalize(glm::cross(camera.up, forward));
  const glm::dvec3 up = glm::cross(forward, right);
  glm::dmat4 view(1.0);
  for (int i = 0; i < 3; ++i) {
    view[i][0] = right[i];
    view[i][1] = up[i];
    view[i][2] = forward[i];
  }
  view[3][0] = -glm::dot(right, camera.eye);
  view[3][1] = -glm::dot(up, camera.eye);
  view[3][2] = -glm::dot(forward, camera.eye);
  return view;
}

// D3DXMatrixPerspectiveFovLH (= glm::perspectiveLH_ZO): z_ndc = 0 at the near plane and
// 1 at the far plane, w_clip = z_view.
glm::dmat4 projection_matrix(const Camera& camera, double aspect) {
  const double y_scale = 1.0 / std::tan(camera.fovy_degrees * std::numbers::pi / 360.0);
  const double x_scale = y_scale / aspect;
  const double depth_range = camera.far_plane - camera.near_plane;
  glm::dmat4 projection(0.0);
  projection[0][0] = x_scale;
  projection[1][1] = y_scale;
  projection[2][2] = camera.far_plane / depth_range;
  projection[2][3] = 1.0;
  projection[3][2] = -camera.near_plane * camera.far_plane / depth_range;
  return projection;
}

}  // namespace reference
