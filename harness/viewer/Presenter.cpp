#include "viewer/Presenter.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace shaderbed::viewer {

PresentApi present_api_of(const std::string& backend) {
  return backend == "vulkan" ? PresentApi::vulkan : PresentApi::gl;
}

const char* api_name(PresentApi api) { return api == PresentApi::vulkan ? "vulkan" : "gl"; }

Placement place(int fb_width, int fb_height, int image_width, int image_height) {
  const int room_width = fb_width - 2 * kFrame, room_height = fb_height - 2 * kFrame;
  if (image_width <= 0 || image_height <= 0 || room_width <= 0 || room_height <= 0) return {};
  // Scaled to fit inside the frame, centred; whole pixels when it fits at 1:1 or more.
  double zoom = std::min(double(room_width) / image_width, double(room_height) / image_height);
  if (zoom >= 1) zoom = std::floor(zoom);
  Placement p;
  p.zoom = zoom;
  p.width = int(std::lround(image_width * zoom));
  p.height = int(std::lround(image_height * zoom));
  p.x = (fb_width - p.width) / 2;
  // Centred as GL centres it from the bottom: the same rows on both APIs.
  p.y = fb_height - p.height - (fb_height - p.height) / 2;
  return p;
}

std::optional<std::pair<int, int>> pixel_at(const Placement& p, double fb_x, double fb_y) {
  if (p.empty() || fb_x < p.x || fb_y < p.y || fb_x >= p.x + p.width || fb_y >= p.y + p.height) return std::nullopt;
  // As scaled() picks them: window pixel (x, y) shows image pixel floor((x + 0.5) / zoom).
  const int column = int(std::floor((std::floor(fb_x - p.x) + 0.5) / p.zoom));
  const int row = int(std::floor((std::floor(fb_y - p.y) + 0.5) / p.zoom));
  const int width = int(std::lround(p.width / p.zoom)), height = int(std::lround(p.height / p.zoom));
  return std::pair{std::clamp(column, 0, width - 1), std::clamp(row, 0, height - 1)};
}

DisplayImage scaled(const DisplayImage& image, const Placement& p) {
  if (p.empty() || image.width <= 0 || image.height <= 0) return {};
  if (p.width == image.width && p.height == image.height) return image;
  DisplayImage out{p.width, p.height, std::vector<uint8_t>(size_t(p.width) * p.height * 3)};
  std::vector<int> column(size_t(p.width));
  for (int x = 0; x < p.width; ++x) column[size_t(x)] = std::min(int((x + 0.5) / p.zoom), image.width - 1);
  for (int y = 0; y < p.height; ++y) {
    const int row = std::min(int((y + 0.5) / p.zoom), image.height - 1);
    const uint8_t* from = &image.rgb[size_t(row) * image.width * 3];
    uint8_t* to = &out.rgb[size_t(y) * p.width * 3];
    for (int x = 0; x < p.width; ++x) std::memcpy(to + size_t(x) * 3, from + size_t(column[size_t(x)]) * 3, 3);
  }
  return out;
}

}  // namespace shaderbed::viewer
