#pragma once
// An SH case's light (`[sh] light`), turned by the case's rotation: its coefficients as the
// GPU gets them (projected in its own frame, then rotated in SH, as D3DXSHRotate does) and
// the exact radiance a reference integrates (the light itself turned, not its SH).
#include <functional>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/Error.h"
#include "scene/CaseFile.h"
#include "scene/Scene.h"
#include "sh/TransferScene.h"

namespace shaderbed {

// The Gauss-Legendre product rule (theta x phi nodes) of the exact radiance of the lights
// that are not deltas (ShLight.cpp says why it is fine enough).
inline constexpr int kExactQuadratureTheta = 96, kExactQuadraturePhi = 192;

class ShLight {
 public:
  virtual ~ShLight() = default;
  // RGB coefficients in the SH frame, rotated.
  virtual std::vector<glm::dvec3> coefficients(int bands) const = 0;
  // The exact outgoing radiance of an unshadowed diffuse point, by its scene-frame normal.
  virtual std::function<glm::dvec3(const glm::dvec3&)> exact_unshadowed(const glm::dvec3& albedo) const = 0;
  // The exact outgoing radiance at a surface point of the transfer scene, with its visibility.
  virtual glm::dvec3 exact_at(const sh::TransferScene& scene, const glm::dvec3& point, const glm::dvec3& normal,
                              const glm::dvec3& albedo, bool shadowed) const = 0;
};

// `turn`: a rotation of the scene frame (y up) applied to the light.
Result<std::unique_ptr<ShLight>> make_sh_light(const ShSetup& setup, const Case& c, const SceneSetup& scene,
                                               const glm::dmat3& turn);

}  // namespace shaderbed
