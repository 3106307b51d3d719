#pragma once
// The pixel inspector in the window: its head line and the listing it printed on stdout
// (twin/PixelListing.h), drawn over the half of the image away from the inspected pixel
// (viewer/TextPanel.h). The line whose value matches nothing in the original, and its
// source line, are in a warm colour; when the listing does not fit, the rows shown are
// those around that line (the first lines else), with "..." rows for the ones left out;
// files are named without their folders (the window is narrow).
#include <string>
#include <vector>

#include "viewer/SplitView.h"
#include "viewer/TextPanel.h"

namespace shaderbed::viewer {

constexpr Rgb kPanelTextColour{224, 224, 224};
constexpr Rgb kPanelDepartsColour{255, 160, 64};   // the line that matches nothing

// The rows shown in a panel of `rows` rows: `head`, then `listing`'s lines.
std::vector<TextLine> inspection_lines(const std::string& head, const std::string& listing, int rows);

// The panel's rectangle in `image` (its pixels rows 0..image.height-1, as the cell's):
// the whole width, at most half the height, at the bottom when `pixel_y` is in the upper
// half, else at the top.
PanelRect inspection_panel_rect(const DisplayImage& image, int pixel_y, int line_count);

void draw_inspection_panel(DisplayImage& image, int pixel_y, const std::string& head, const std::string& listing);

}  // namespace shaderbed::viewer
