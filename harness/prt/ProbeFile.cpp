#include "prt/ProbeFile.h"

#include <filesystem>
#include <vector>

#include "imageio/ImageIoModule.h"

namespace shaderbed {

Result<sh::EnvironmentMap> read_probe(const std::string& path, sh::MapLayout layout) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return fail(ErrorStage::sh, path + ": no such file");
  auto image = read_image_file(path);
  if (!image) return std::unexpected(image.error());
  if (auto ok = sh::check_image_shape(path, {image->width, image->height, 1, image->channels, false}, layout); !ok)
    return fail(ErrorStage::sh, ok.error());
  std::vector<glm::vec3> pixels(size_t(image->width) * size_t(image->height));
  for (size_t p = 0; p < pixels.size(); ++p) {
    const float* v = &image->values[p * size_t(image->channels)];
    pixels[p] = image->channels >= 3 ? glm::vec3(v[0], v[1], v[2]) : glm::vec3(v[0]);
  }
  auto map = sh::EnvironmentMap::from_pixels(layout, image->width, image->height, std::move(pixels));
  if (!map) return fail(ErrorStage::sh, path + ": " + map.error());
  return std::move(*map);
}

std::string naming_file(const std::string& path, const std::string& message) {
  return message.find(path) == std::string::npos ? path + ": " + message : message;
}

}  // namespace shaderbed
