// The viewer's text (viewer/TextPanel.h, viewer/InspectionPanel.h): glyphs from the font's
// own atlas land where the font puts them, in the panel's rectangle and nowhere else.
#include <gtest/gtest.h>

#include "viewer/InspectionPanel.h"
#include "viewer/TextPanel.h"

namespace shaderbed::viewer {
namespace {

constexpr Rgb kWhite{255, 255, 255};
constexpr uint8_t kGrey = 120;

DisplayImage grey(int width, int height) {
  return {width, height, std::vector<uint8_t>(size_t(width) * size_t(height) * 3, kGrey)};
}

Rgb pixel(const DisplayImage& image, int x, int y) {
  const uint8_t* p = &image.rgb[(size_t(y) * size_t(image.width) + size_t(x)) * 3];
  return {p[0], p[1], p[2]};
}

constexpr uint8_t kShaded = kGrey * kBackgroundShade / 256;

TEST(ViewerText, TheFontIsMonospacedAndHasGlyphs) {
  EXPECT_EQ(text_advance(), 7);        // ProggyClean
  EXPECT_EQ(text_line_height(), 13);
  int lit = 0;
  for (int y = 0; y < text_line_height(); ++y)
    for (int x = 0; x < text_advance(); ++x) {
      lit += glyph_alpha('A', x, y) > 0;
      EXPECT_EQ(glyph_alpha(' ', x, y), 0);
    }
  EXPECT_GT(lit, 8);
}

TEST(ViewerText, GlyphsAppearWhereTheFontPutsThemAndNothingOutsideTheRegion) {
  DisplayImage image = grey(120, 60);
  const PanelRect region{10, 20, 60, 30};
  const std::string text = "Hi|0";
  draw_text_panel(image, region, {{text, kWhite}});
  const int left = region.x + kTextPadding, top = region.y + kTextPadding;
  int glyph_pixels = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const Rgb p = pixel(image, x, y);
      const bool inside = x >= region.x && x < region.x + region.width && y >= region.y && y < region.y + region.height;
      if (!inside) {
        ASSERT_EQ(p, (Rgb{kGrey, kGrey, kGrey})) << "outside the region at " << x << "," << y;
        continue;
      }
      // In the text's cells: the font's alpha blended over the shaded background.
      const int column = (x - left) / text_advance();
      const bool in_text = x >= left && y >= top && column < int(text.size()) && y < top + text_line_height();
      const int a = in_text ? glyph_alpha(text[size_t(column)], (x - left) % text_advance(), y - top) : 0;
      const uint8_t expected = uint8_t((kShaded * (255 - a) + 255 * a + 127) / 255);
      ASSERT_EQ(p, (Rgb{expected, expected, expected})) << "at " << x << "," << y;
      glyph_pixels += a == 255;
    }
  EXPECT_GT(glyph_pixels, 20);
}

TEST(ViewerText, LongLinesAreCutAndOnlyWholeRowsAreDrawn) {
  DisplayImage image = grey(80, 40);
  const PanelRect region{0, 0, 80, 2 * kTextPadding + text_line_height() + 5};   // one row and a bit
  draw_text_panel(image, region, {{std::string(100, 'W'), kWhite}, {"second", kWhite}});
  EXPECT_EQ(columns_in(80), (80 - 2 * kTextPadding) / text_advance());
  // The cut line ends with "...": the last column's cell holds a '.', not a 'W'.
  const int last = kTextPadding + (columns_in(80) - 1) * text_advance();
  for (int y = 0; y < text_line_height(); ++y)
    for (int x = 0; x < text_advance(); ++x) {
      const uint8_t expected = glyph_alpha('.', x, y) == 255 ? 255 : kShaded;
      ASSERT_EQ(pixel(image, last + x, kTextPadding + y)[0], expected) << x << "," << y;
    }
  // No second row: below the first, only the shaded background and then the image.
  for (int y = kTextPadding + text_line_height(); y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      ASSERT_EQ(pixel(image, x, y)[0], y < region.height ? kShaded : kGrey) << x << "," << y;
}

TEST(ViewerText, TheInspectionShowsTheLineThatMatchesNothingInAWarmColour) {
  const std::string listing =
      "a.frag:10  float a = 1.0;\n      a = 1   matches cases/hlsl/original.hlsl:3 a\n"
      "glsl/a.frag:11  float b = -a;\n      b = -1   matches nothing\n"
      "a.frag:12  gl_FragColor = vec4(b);\n      = (-1, -1, -1, -1)\n";
  const std::vector<TextLine> all = inspection_lines("pixel (1, 2) of cell", listing, 20);
  ASSERT_EQ(all.size(), 7u);
  EXPECT_EQ(all[0].text, "pixel (1, 2) of cell");
  EXPECT_EQ(all[2].text, "      a = 1   matches original.hlsl:3 a");   // files without their folders
  for (size_t i = 0; i < all.size(); ++i)
    EXPECT_EQ(all[i].colour, i == 3 || i == 4 ? kPanelDepartsColour : kPanelTextColour) << all[i].text;
  // Four rows: the head, then the rows around the warm line, the others counted.
  const std::vector<TextLine> some = inspection_lines("head", listing, 4);
  ASSERT_EQ(some.size(), 4u);
  EXPECT_EQ(some[1].text, "... 2 lines above");
  EXPECT_EQ(some[2].text, "a.frag:11  float b = -a;");
  EXPECT_EQ(some[2].colour, kPanelDepartsColour);
  EXPECT_EQ(some[3].text, "... 3 more lines");
}

TEST(ViewerText, ThePanelTakesTheHalfAwayFromThePixel) {
  const DisplayImage image = grey(256, 256);
  const PanelRect low = inspection_panel_rect(image, 16, 100);
  EXPECT_EQ(low.y, 128);
  EXPECT_EQ(low.height, 128);
  EXPECT_EQ(low.width, 256);
  const PanelRect high = inspection_panel_rect(image, 200, 2);
  EXPECT_EQ(high.y, 0);
  EXPECT_EQ(high.height, 2 * text_line_height() + 2 * kTextPadding);
}

}  // namespace
}  // namespace shaderbed::viewer
