#include "reference/Surface.h"

#include "reference/ObjectSpace.h"
#include "reference/StableVector.h"
#include "reference/VisibleSurface.h"

namespace reference {

std::expected<SurfaceBuffer, std::string> render_surface(const Scene& scene) {
  auto visibility = rasterise_scene(scene);
  if (!visibility) return std::unexpected(visibility.error());
  const ObjectSpaceLighting lighting = to_object_space(scene.lights, scene.camera, scene.world);
  const bool point_light = scene.light == SceneLight::point;

  const size_t pixel_count = static_cast<size_t>(scene.width) * scene.height;
  SurfaceBuffer surface{scene.width, scene.height, std::vector<SurfaceSample>(pixel_count),
                        std::vector<uint8_t>(pixel_count, 0)};
  for (size_t pixel = 0; pixel < pixel_count; ++pixel) {
    const VisibleSample& visible = visibility->samples[pixel];
    if (!visible.covered()) continue;
    const SurfacePoint point = interpolate_surface(scene.mesh, visible);
    SurfaceSample& sample = surface.samples[pixel];
    sample.position = point.position;
    sample.normal = point.normal;
    sample.to_light =
        point_light ? stable::normalize(lighting.light_position - point.position) : lighting.light_direction;
    sample.to_eye = stable::normalize(lighting.eye_position - point.position);
    sample.uv = point.uv;
    surface.coverage[pixel] = 1;
  }
  return surface;
}

}  // namespace reference
