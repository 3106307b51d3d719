#pragma once
// What the window shows, as 8-bit RGB: the render alone, or render | reference | error
// heat map side by side. Each panel looks exactly like the PNG `run --out` writes for it
// (compare/ImageFiles.h): colours clamped, NaN/Inf magenta, uncovered pixels slate, and
// the error map in false colour from 0 to the worst interior error (compare/ErrorMap.h), as
// in the HTML report.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "compare/ImageComparison.h"
#include "core/Image.h"

namespace shaderbed::viewer {

struct DisplayImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;   // rows top to bottom
};

constexpr int kSplitGap = 2;   // black pixels between the panels

DisplayImage render_panel(const Image& render);
DisplayImage reference_panel(const ReferenceImage& reference);
// |render - reference| as compare/ErrorMap.h colours it (`interior_threshold`: the absolute part).
DisplayImage error_panel(const Image& error, double interior_threshold);
// A panel with nothing to show (no reference could be drawn): background only.
DisplayImage empty_panel(int width, int height);

// Panels left to right with kSplitGap black columns between them.
DisplayImage side_by_side(const std::vector<DisplayImage>& panels);

// The pixel of one panel under pixel (x, y) of `panels` panels panel_width wide laid side
// by side (each panel shows the same pixels of the cell); none in a gap or outside.
std::optional<std::pair<int, int>> panel_pixel(int x, int y, int panel_width, int panel_height, int panels);

// The reference as a float image (what the screenshot's EXR holds, and what the panel shows).
Image reference_as_image(const ReferenceImage& reference);

}  // namespace shaderbed::viewer
