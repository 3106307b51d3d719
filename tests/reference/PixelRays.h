#pragma once
// Test helper: where the ray through a pixel centre meets a plane, computed
// analytically (independently of the rasteriser) from the inverse camera transform.
#include <glm/glm.hpp>

namespace reference::testing {

inline glm::dvec3 pixel_ray_hit(const glm::dmat4& world_to_clip, const glm::dvec3& eye, int width, int height, int x,
                                int y, const glm::dvec3& plane_point, const glm::dvec3& plane_normal) {
  const glm::dvec2 ndc(2.0 * (x + 0.5) / width - 1.0, 1.0 - 2.0 * (y + 0.5) / height);
  const glm::dvec4 far_point = glm::inverse(world_to_clip) * glm::dvec4(ndc, 1.0, 1.0);
  const glm::dvec3 direction = glm::dvec3(far_point) / far_point.w - eye;
  const double t = glm::dot(plane_point - eye, plane_normal) / glm::dot(direction, plane_normal);
  return eye + t * direction;
}

}  // namespace reference::testing
