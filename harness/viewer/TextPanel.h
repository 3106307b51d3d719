#pragma once
// Text in the image the window shows: lines of text drawn on the CPU into a rectangle of a
// DisplayImage, over a dark translucent background, so both presenters (GL and Vulkan)
// show it alike and a screenshot holds it. The glyphs are Dear ImGui's built-in font
// (ProggyClean, 13 px, monospaced), taken from its font atlas only: no ImGui context and
// no render backend.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "viewer/SplitView.h"

namespace shaderbed::viewer {

using Rgb = std::array<uint8_t, 3>;

struct TextLine {
  std::string text;   // ASCII shows as is; a tab is a space, any other byte a '?'
  Rgb colour{};
};

struct PanelRect {
  int x = 0, y = 0, width = 0, height = 0;
};

// The font's cell: every glyph advances the pen by advance() pixels; lines are
// line_height() apart.
int text_advance();
int text_line_height();
// The font's alpha (0..255) at (dx, dy) of character c's cell, as draw_text_panel blends
// it (0 outside the glyph's pixels).
int glyph_alpha(char c, int dx, int dy);

constexpr int kTextPadding = 3;                  // pixels between the rectangle's edge and the text
constexpr int kBackgroundShade = 64;             // of 256: the image under the panel, darkened to a quarter

// Darkens `region` (clipped to the image) and draws `lines` in it, top to bottom from
// (region.x + kTextPadding, region.y + kTextPadding): as many as fit whole, each cut to
// the width with "..." at its end. Nothing outside the region changes.
void draw_text_panel(DisplayImage& image, PanelRect region, const std::vector<TextLine>& lines);

// How many characters of a line fit in a panel `width` pixels wide, and how many lines
// in one `height` pixels high.
int columns_in(int width);
int rows_in(int height);

}  // namespace shaderbed::viewer
