#pragma once
// HDR environment maps (.hdr, .exr, anything OpenImageIO reads) as radiance functions of
// a direction in the SH frame, with bilinear lookup, in two layouts:
//
// lat-long: the book's own angles. Pixel (x, y), row 0 at the top, covers
//   phi in [2 pi x / W, 2 pi (x+1) / W) from +x toward +y, theta in [pi y / H, pi (y+1) / H)
//   from +z (SH up = scene +y): the top row is the zenith, the left edge phi = 0. Any W x H.
// angular (Debevec's light probe): square. In the probe's frame, which is the scene's
//   (y up, x right), direction D sits at (u, v) = (D_x r, D_y r) with
//   r = acos(D_z) / (pi sqrt(D_x^2 + D_y^2)), u rightward and v upward in [-1, 1]^2:
//   the image centre looks along the probe's +z ("forward"), the rim is -z, and the
//   distance from the centre is proportional to the angle from forward. SH direction
//   w = to_sh_frame(D) = (D_x, -D_z, D_y): forward is SH -y, up is SH +z.
// Both sample radiance at pixel centres; lookups interpolate bilinearly between them
// (lat-long wraps in phi and clamps at the poles; angular clamps at the image edge).
#include <expected>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "sh/Lights.h"
#include "sh/Projection.h"

namespace sh {

enum class MapLayout { latlong, angular };

// Where a direction (SH frame, any length > 0) falls, and back.
glm::dvec2 latlong_coordinates(const glm::dvec3& direction);  // (phi / 2 pi, theta / pi) in [0, 1]^2
glm::dvec3 latlong_direction(const glm::dvec2& uv);
glm::dvec2 angular_coordinates(const glm::dvec3& direction);  // Debevec's (u, v) in the unit disc
// Any (u, v): beyond the rim the angle from forward keeps growing as pi r, so the map
// extends smoothly past the disc (used for the pixels outside it).
glm::dvec3 angular_direction(const glm::dvec2& uv);

class EnvironmentMap {
 public:
  // Reads the first subimage; 1 channel is grey, 2 are grey and alpha, 3 or more begin
  // with R, G, B (alpha ignored). Errors name the file: missing, unreadable, not a 2D
  // image, empty, or an angular map that is not square.
  static std::expected<EnvironmentMap, std::string> read(const std::filesystem::path& path, MapLayout layout);
  // From RGB pixels, row major, top row first (width * height of them).
  static std::expected<EnvironmentMap, std::string> from_pixels(MapLayout layout, int width, int height,
                                                                std::vector<glm::vec3> pixels);

  MapLayout layout() const { return layout_; }
  int width() const { return width_; }
  int height() const { return height_; }
  glm::dvec3 pixel(int x, int y) const { return glm::dvec3(pixels_[std::size_t(y) * width_ + x]); }

  // The radiance toward `direction` (SH frame), bilinear between pixel centres.
  glm::dvec3 lookup(const glm::dvec3& direction) const;
  glm::dvec3 operator()(const glm::dvec3& direction) const { return lookup(direction); }

 private:
  EnvironmentMap(MapLayout layout, int width, int height, std::vector<glm::vec3> pixels)
      : layout_(layout), width_(width), height_(height), pixels_(std::move(pixels)) {}
  glm::dvec3 bilinear(double x, double y, bool wrap_x) const;

  MapLayout layout_;
  int width_, height_;
  std::vector<glm::vec3> pixels_;
};

// What read() asks of an image before its pixels: a flat 2D image (depth 1, not deep), not
// empty, and square for the angular layout. The error names the file.
struct ImageShape {
  int width = 0, height = 0, depth = 1, channels = 0;
  bool deep = false;
};
std::expected<void, std::string> check_image_shape(const std::filesystem::path& path, const ImageShape& shape,
                                                   MapLayout layout);

// Writes `radiance` sampled at the pixel centres as a float RGB image in that layout; the
// format follows the extension (.exr, .hdr, ...).
std::expected<void, std::string> write_environment(const std::filesystem::path& path, MapLayout layout, int width,
                                                   int height, const RgbFunction& radiance);
// The analytic sky (Lights.h) as a lat-long EXR: the project's environment maps are made, not shipped.
std::expected<void, std::string> write_sky_latlong(const std::filesystem::path& path, int width, int height,
                                                   const SkyLight& sky = {});

}  // namespace sh
