#include "compare/ImageFiles.h"

#include <algorithm>
#include <cmath>

#include "imageio/ImageIoModule.h"

namespace shaderbed {

Result<void> write_exr(const std::string& path, int width, int height, const std::vector<float>& rgba) {
  return write_image_file(path, width, height, 4, PixelType::float32, rgba.data());
}

Result<void> write_png(const std::string& path, const Image& image, float scale) {
  const std::vector<uint8_t> bytes = png_pixels(image, scale);
  return write_image_file(path, image.width, image.height, 3, PixelType::uint8, bytes.data());
}

std::vector<uint8_t> png_pixels(const Image& image, float scale) {
  // Opaque, with uncovered pixels in a dark slate so white surfaces stay visible.
  constexpr float kBackground[3] = {0.10f, 0.11f, 0.14f};
  std::vector<uint8_t> bytes(size_t(image.width) * image.height * 3);
  for (size_t i = 0; i < size_t(image.width) * image.height; ++i) {
    const float* p = &image.rgba[i * 4];
    uint8_t* o = &bytes[i * 3];
    const bool covered = image.coverage.empty() || image.coverage[i];
    const bool finite = std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
    for (int c = 0; c < 3; ++c) {
      const float v = !covered ? kBackground[c] : finite ? std::clamp(p[c] * scale, 0.0f, 1.0f) : (c == 1 ? 0.0f : 1.0f);
      o[c] = static_cast<uint8_t>(std::lround(v * 255.0f));
    }
  }
  return bytes;
}

}  // namespace shaderbed
