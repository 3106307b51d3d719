// HDR environment maps (EnvironmentMap.h): OpenImageIO for the file, the two layouts' maps
// between pixels and directions, and bilinear lookup.
#include "sh/EnvironmentMap.h"


#include <algorithm>
#include <cmath>
#include <numbers>
#include <system_error>

#include "sh/Basis.h"

namespace sh {

namespace {

constexpr double pi = std::numbers::pi;

std::string named(const std::filesystem::path& path, const std::string& what) { return path.string() + ": " + what; }

}  // namespace

glm::dvec2 latlong_coordinates(const glm::dvec3& w) {
  // atan2 rather than acos: accurate near the poles, and indifferent to |w|.
  double phi = std::atan2(w.y, w.x);
  if (phi < 0.0) phi += 2.0 * pi;
  const double theta = std::atan2(std::hypot(w.x, w.y), w.z);
  return {phi / (2.0 * pi), theta / pi};
}

glm::dvec3 latlong_direction(const glm::dvec2& uv) {
  const double phi = 2.0 * pi * uv.x, theta = pi * uv.y;
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

glm::dvec2 angular_coordinates(const glm::dvec3& w) {
  const glm::dvec3 d = from_sh_frame(w);
  const double sideways = std::hypot(d.x, d.y);
  if (sideways == 0.0) return d.z >= 0.0 ? glm::dvec2(0.0) : glm::dvec2(1.0, 0.0);  // forward; backward is the rim
  // r = acos(D_z) / (pi sqrt(D_x^2 + D_y^2)), the angle from forward taken by atan2.
  const double r = std::atan2(sideways, d.z) / (pi * sideways);
  return {d.x * r, d.y * r};
}

glm::dvec3 angular_direction(const glm::dvec2& uv) {
  const double r = std::hypot(uv.x, uv.y);
  if (r == 0.0) return to_sh_frame({0.0, 0.0, 1.0});
  const double theta = pi * r;
  const double s = std::sin(theta) / r;
  return to_sh_frame({uv.x * s, uv.y * s, std::cos(theta)});
}

std::expected<EnvironmentMap, std::string> EnvironmentMap::from_pixels(MapLayout layout, int width, int height,
                                                                       std::vector<glm::vec3> pixels) {
  if (auto ok = check_image_shape("pixels", {width, height, 1, 3}, layout); !ok) return std::unexpected(ok.error());
  if (pixels.size() != std::size_t(width) * height)
    return std::unexpected("pixels: " + std::to_string(pixels.size()) + " of them for " + std::to_string(width) + "x" +
                           std::to_string(height));
  return EnvironmentMap(layout, width, height, std::move(pixels));
}

std::expected<void, std::string> check_image_shape(const std::filesystem::path& path, const ImageShape& shape,
                                                   MapLayout layout) {
  if (shape.depth > 1)
    return std::unexpected(named(path, "not a 2D image (a volume " + std::to_string(shape.depth) + " deep)"));
  if (shape.deep) return std::unexpected(named(path, "not a flat 2D image (deep data)"));
  if (shape.width <= 0 || shape.height <= 0 || shape.channels <= 0) return std::unexpected(named(path, "empty image"));
  if (layout == MapLayout::angular && shape.width != shape.height)
    return std::unexpected(named(
        path, "angular map must be square, is " + std::to_string(shape.width) + "x" + std::to_string(shape.height)));
  return {};
}

glm::dvec3 EnvironmentMap::bilinear(double x, double y, bool wrap_x) const {
  const double fx = std::floor(x), fy = std::floor(y);
  const double tx = x - fx, ty = y - fy;
  auto column = [&](long long i) {
    if (wrap_x) return int(((i % width_) + width_) % width_);
    return int(std::clamp<long long>(i, 0, width_ - 1));
  };
  auto row = [&](long long j) { return int(std::clamp<long long>(j, 0, height_ - 1)); };
  const int x0 = column((long long)fx), x1 = column((long long)fx + 1);
  const int y0 = row((long long)fy), y1 = row((long long)fy + 1);
  return (1.0 - ty) * ((1.0 - tx) * pixel(x0, y0) + tx * pixel(x1, y0)) +
         ty * ((1.0 - tx) * pixel(x0, y1) + tx * pixel(x1, y1));
}

glm::dvec3 EnvironmentMap::lookup(const glm::dvec3& direction) const {
  // Pixel centres sit at half-integers: continuous coordinate c maps to pixel c - 0.5.
  if (layout_ == MapLayout::latlong) {
    const glm::dvec2 uv = latlong_coordinates(direction);
    return bilinear(uv.x * width_ - 0.5, uv.y * height_ - 0.5, true);
  }
  const glm::dvec2 uv = angular_coordinates(direction);
  return bilinear(0.5 * (uv.x + 1.0) * width_ - 0.5, 0.5 * (1.0 - uv.y) * height_ - 0.5, false);
}

}  // namespace sh
