#include "compare/SurfaceSamples.h"

#include "reference/Surface.h"

namespace shaderbed {

SurfaceSamples surface_samples(const reference::SurfaceBuffer& surface) {
  const size_t count = surface.samples.size();
  SurfaceSamples out{surface.width, surface.height, std::vector<double>(count, 0.0), std::vector<double>(count, 0.0),
                     std::vector<double>(count, 0.0)};
  for (size_t pixel = 0; pixel < count; ++pixel) {
    if (!surface.coverage[pixel]) continue;
    const reference::SurfaceSample& sample = surface.samples[pixel];
    const double length = glm::length(sample.normal);
    if (length <= 0) continue;  // a degenerate interpolated normal: no direction to report
    const glm::dvec3 normal = sample.normal / length;
    out.n_dot_l[pixel] = glm::dot(normal, sample.to_light);
    out.n_dot_v[pixel] = glm::dot(normal, sample.to_eye);
    out.normal_length[pixel] = length;
  }
  return out;
}

}  // namespace shaderbed
