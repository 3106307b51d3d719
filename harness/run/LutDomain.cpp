#include "run/LutDomain.h"

#include <algorithm>
#include <cmath>

#include "compare/ImageComparison.h"
#include "run/ReferenceRender.h"
#include "reference/Reference.h"
#include "reference/Surface.h"

namespace shaderbed {
namespace {

double max_of(const Case& c, const std::string& name) {
  auto it = c.params.find(name);
  return it == c.params.end() || it->second.empty() ? 1.0 : *std::max_element(it->second.begin(), it->second.end());
}

struct Shading {
  glm::dvec3 spot_axis{0.0};     // object-space L of the directional light (Warn's spot axis)
  glm::dvec3 light_position{0.0};
  double intensity = 1;          // max(diffuse) * max(light_color); 1 without a light colour
};

LutSample configuration(const glm::dvec3& position, const glm::dvec3& normal, const glm::dvec3& to_light,
                        const glm::dvec3& to_eye, const Shading& shading) {
  const double length = glm::length(normal);
  const glm::dvec3 n = length > 0 ? normal / length : glm::dvec3(0.0);
  const glm::dvec3 l = glm::normalize(to_light), v = glm::normalize(to_eye);
  const glm::dvec3 half = l + v;
  LutSample x;
  x.n_dot_l = glm::dot(n, l);
  x.n_dot_v = glm::dot(n, v);
  x.n_dot_h = glm::length(half) > 0 ? glm::dot(n, glm::normalize(half)) : 0.0;
  // cosC as the model defines it (errata E8): 0 when either projection vanishes.
  const glm::dvec3 eye_in_plane = v - n * x.n_dot_v, light_in_plane = l - n * x.n_dot_l;
  x.cos_azimuth = glm::dot(eye_in_plane, eye_in_plane) < 1e-12 || glm::dot(light_in_plane, light_in_plane) < 1e-12
                      ? 0.0
                      : std::max(0.0, glm::dot(glm::normalize(eye_in_plane), glm::normalize(light_in_plane)));
  x.spot_cos = glm::dot(l, shading.spot_axis);
  const double d2 = glm::dot(shading.light_position - position, shading.light_position - position);
  x.light_scale = d2 > 0 ? shading.intensity / d2 : shading.intensity;
  return x;
}

}  // namespace

Result<LutDomain> lut_domain(const Case& c, const Mesh& mesh, const SceneSetup& setup, const std::string& shape) {
  const reference::Scene scene = surface_scene(mesh, setup, c);
  auto surface = reference::render_surface(scene);
  if (!surface) return std::unexpected(Error{.message = surface.error(), .file = c.path, .stage = ErrorStage::lut});
  const glm::dmat4 object_from_world = glm::inverse(setup.world);
  Shading shading;
  shading.spot_axis = glm::normalize(glm::dvec3(object_from_world * glm::dvec4(setup.lights.direction, 0.0)));
  shading.light_position = glm::dvec3(object_from_world * glm::dvec4(setup.lights.position, 1.0));
  if (c.params.contains("light_color")) shading.intensity = max_of(c, "diffuse") * max_of(c, "light_color");

  const int w = surface->width, h = surface->height;
  const ReferenceImage coverage{w, h, {}, surface->coverage};
  const std::vector<PixelClass> classes = classify_pixels(coverage);
  const auto covered = [&](int x, int y) { return x >= 0 && y >= 0 && x < w && y < h && surface->coverage[size_t(y) * w + x]; };
  const auto at = [&](int x, int y) -> const reference::SurfaceSample& { return surface->samples[size_t(y) * w + x]; };
  const auto sample = [&](const reference::SurfaceSample& s) {
    return configuration(s.position, s.normal, s.to_light, s.to_eye, shading);
  };

  LutDomain domain{.shape = shape, .interior = {}, .band = {}};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const PixelClass k = classes[size_t(y) * w + x];
      if (k == PixelClass::interior) domain.interior.push_back(sample(at(x, y)));
      if (k != PixelClass::silhouette) continue;
      // A band pixel is matched at itself or a neighbour, and the GPU may shade it with
      // attributes extrapolated past the triangle: every covered pixel p of the 3x3, and p
      // pushed one pixel away from each covered neighbour q (2p - q, linear in the
      // attributes as the rasteriser's plane equations are).
      for (int py = y - 1; py <= y + 1; ++py)
        for (int px = x - 1; px <= x + 1; ++px) {
          if (!covered(px, py)) continue;
          const reference::SurfaceSample& p = at(px, py);
          domain.band.push_back(sample(p));
          for (int qy = py - 1; qy <= py + 1; ++qy)
            for (int qx = px - 1; qx <= px + 1; ++qx) {
              if ((qx == px && qy == py) || !covered(qx, qy)) continue;
              const reference::SurfaceSample& q = at(qx, qy);
              domain.band.push_back(configuration(2.0 * p.position - q.position, 2.0 * p.normal - q.normal,
                                                  2.0 * p.to_light - q.to_light, 2.0 * p.to_eye - q.to_eye, shading));
            }
        }
    }
  return domain;
}

}  // namespace shaderbed
