#include "viewer/TextPanel.h"

#include <algorithm>
#include <cmath>

#include <imgui.h>

namespace shaderbed::viewer {
namespace {

// ImGui's default font, rasterised once into an alpha atlas (no ImGui context needed).
struct FontAtlas {
  ImFontAtlas atlas;
  ImFont* font = nullptr;
  const unsigned char* alpha = nullptr;
  int width = 0, height = 0;
  int advance = 7, line_height = 13;

  FontAtlas() {
    font = atlas.AddFontDefault();
    unsigned char* pixels = nullptr;
    atlas.GetTexDataAsAlpha8(&pixels, &width, &height);
    alpha = pixels;
    advance = int(std::lround(font->FindGlyph('M')->AdvanceX));
    line_height = int(std::lround(font->FontSize));
  }

  // The glyph drawn for byte c.
  const ImFontGlyph* glyph(char c) const {
    const unsigned char u = static_cast<unsigned char>(c);
    const ImWchar w = u == '\t' ? ImWchar(' ') : u < 0x20 || u >= 0x7f ? ImWchar('?') : ImWchar(u);
    return font->FindGlyph(w);
  }

  // Alpha at (dx, dy) of the cell of c, the pen at the cell's top left.
  int alpha_at(char c, int dx, int dy) const {
    const ImFontGlyph* g = glyph(c);
    if (!g || !g->Visible) return 0;
    const int x0 = int(std::lround(g->X0)), y0 = int(std::lround(g->Y0));
    const int gw = int(std::lround(g->X1 - g->X0)), gh = int(std::lround(g->Y1 - g->Y0));
    const int gx = dx - x0, gy = dy - y0;
    if (gx < 0 || gy < 0 || gx >= gw || gy >= gh) return 0;
    const int u = int(std::lround(g->U0 * float(width))) + gx;
    const int v = int(std::lround(g->V0 * float(height))) + gy;
    return alpha[size_t(v) * size_t(width) + size_t(u)];
  }
};

const FontAtlas& font() {
  static const FontAtlas atlas;
  return atlas;
}

// "?" for what the font does not draw; bytes of a UTF-8 sequence after its first are dropped.
std::string printable(const std::string& text) {
  std::string out;
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80 && u < 0xc0) continue;
    out += u == '\t' ? ' ' : (u < 0x20 || u >= 0x7f) ? '?' : c;
  }
  return out;
}

}  // namespace

int text_advance() { return font().advance; }
int text_line_height() { return font().line_height; }
int glyph_alpha(char c, int dx, int dy) { return font().alpha_at(c, dx, dy); }

int columns_in(int width) { return std::max(0, (width - 2 * kTextPadding) / text_advance()); }
int rows_in(int height) { return std::max(0, (height - 2 * kTextPadding) / text_line_height()); }

void draw_text_panel(DisplayImage& image, PanelRect region, const std::vector<TextLine>& lines) {
  const int x0 = std::max(region.x, 0), y0 = std::max(region.y, 0);
  const int x1 = std::min(region.x + region.width, image.width), y1 = std::min(region.y + region.height, image.height);
  if (x0 >= x1 || y0 >= y1 || image.rgb.size() < size_t(image.width) * size_t(image.height) * 3) return;
  const auto at = [&](int x, int y) { return &image.rgb[(size_t(y) * size_t(image.width) + size_t(x)) * 3]; };
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int k = 0; k < 3; ++k) at(x, y)[k] = uint8_t(at(x, y)[k] * kBackgroundShade / 256);

  const FontAtlas& f = font();
  const PanelRect clipped{x0, y0, x1 - x0, y1 - y0};
  const int columns = columns_in(clipped.width);
  const int rows = std::min<int>(rows_in(clipped.height), int(lines.size()));
  for (int row = 0; row < rows; ++row) {
    std::string text = printable(lines[size_t(row)].text);
    if (int(text.size()) > columns) text = columns > 3 ? text.substr(0, size_t(columns - 3)) + "..." : text.substr(0, size_t(columns));
    const Rgb& colour = lines[size_t(row)].colour;
    const int top = y0 + kTextPadding + row * f.line_height;
    for (size_t i = 0; i < text.size(); ++i) {
      const int left = x0 + kTextPadding + int(i) * f.advance;
      for (int dy = 0; dy < f.line_height; ++dy)
        for (int dx = 0; dx < f.advance; ++dx) {
          const int a = f.alpha_at(text[i], dx, dy);
          if (a == 0 || left + dx >= x1 || top + dy >= y1) continue;
          uint8_t* p = at(left + dx, top + dy);
          for (int k = 0; k < 3; ++k) p[k] = uint8_t((p[k] * (255 - a) + colour[size_t(k)] * a + 127) / 255);
        }
    }
  }
}

}  // namespace shaderbed::viewer
