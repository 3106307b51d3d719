#include "viewer/SplitView.h"

#include <algorithm>
#include <cstring>

#include "compare/ErrorMap.h"
#include "compare/ImageFiles.h"

namespace shaderbed::viewer {

DisplayImage render_panel(const Image& render) { return {render.width, render.height, png_pixels(render)}; }

std::optional<std::pair<int, int>> panel_pixel(int x, int y, int panel_width, int panel_height, int panels) {
  if (x < 0 || y < 0 || y >= panel_height || panel_width <= 0) return std::nullopt;
  const int pitch = panel_width + kSplitGap;
  if (x / pitch >= panels || x % pitch >= panel_width) return std::nullopt;
  return std::pair{x % pitch, y};
}

Image reference_as_image(const ReferenceImage& reference) {
  Image image(reference.width, reference.height);
  for (size_t i = 0; i < reference.rgba.size(); ++i) image.rgba[i] = float(reference.rgba[i]);
  image.coverage = reference.coverage;
  return image;
}

DisplayImage reference_panel(const ReferenceImage& reference) { return render_panel(reference_as_image(reference)); }

DisplayImage error_panel(const Image& error, double interior_threshold) {
  // The same colours and scale as the run's .error.png (run/GroupRunner.cpp) and the HTML report.
  ErrorMap map = error_map(error, interior_threshold);
  return {map.width, map.height, std::move(map.rgb)};
}

DisplayImage empty_panel(int width, int height) {
  Image blank(width, height);   // nothing covered: the background colour everywhere
  return render_panel(blank);
}

DisplayImage side_by_side(const std::vector<DisplayImage>& panels) {
  DisplayImage out;
  for (const DisplayImage& p : panels) {
    out.width += p.width;
    out.height = std::max(out.height, p.height);
  }
  if (panels.size() > 1) out.width += kSplitGap * int(panels.size() - 1);
  out.rgb.assign(size_t(out.width) * out.height * 3, 0);
  int x0 = 0;
  for (const DisplayImage& p : panels) {
    for (int y = 0; y < p.height; ++y)
      std::memcpy(&out.rgb[(size_t(y) * out.width + x0) * 3], &p.rgb[size_t(y) * p.width * 3], size_t(p.width) * 3);
    x0 += p.width + kSplitGap;
  }
  return out;
}

}  // namespace shaderbed::viewer
