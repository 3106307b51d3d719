#include "reference/ObjectSpace.h"
#include "reference/StableVector.h"

namespace reference {

ObjectSpaceLighting to_object_space(const Lights& lights, const Camera& camera, const glm::dmat4& world) {
  const glm::dmat4 world_to_object = glm::inverse(world);
  const auto position = [&](const glm::dvec3& p) {
    const glm::dvec4 object = world_to_object * glm::dvec4(p, 1.0);
    return glm::dvec3(object) / object.w;  // w stays 1 for an affine world matrix
  };
  return {stable::normalize(glm::dvec3(world_to_object * glm::dvec4(lights.direction, 0.0))), position(lights.position),
          position(camera.eye)};
}

}  // namespace reference
