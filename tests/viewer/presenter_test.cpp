// Where the window puts the image, whichever API presents it: the GL window and the
// Vulkan swapchain place and scale it with the same functions, so both show the same
// pixels at the same place.
#include <gtest/gtest.h>

#include "viewer/Presenter.h"

namespace shaderbed::viewer {
namespace {

TEST(ViewerPresent, EachBackendIsPresentedWithItsOwnApi) {
  EXPECT_EQ(present_api_of("vulkan"), PresentApi::vulkan);
  EXPECT_EQ(present_api_of("gl"), PresentApi::gl);
  EXPECT_STREQ(api_name(PresentApi::vulkan), "vulkan");
}

TEST(ViewerPresent, TheImageIsCentredInsideTheFrameAtAWholeZoom) {
  const Placement exact = place(128 + 2 * kFrame, 128 + 2 * kFrame, 128, 128);
  EXPECT_EQ(exact.x, kFrame);
  EXPECT_EQ(exact.y, kFrame);
  EXPECT_EQ(exact.width, 128);
  EXPECT_EQ(exact.zoom, 1);
  // Larger: whole image pixels per image pixel, centred (rows as GL centres them from the bottom).
  const Placement larger = place(400, 301, 128, 128);
  EXPECT_EQ(larger.zoom, 2);
  EXPECT_EQ(larger.width, 256);
  EXPECT_EQ(larger.x, (400 - 256) / 2);
  EXPECT_EQ(301 - larger.y - larger.height, (301 - 256) / 2);
  // Smaller: scaled down to fit inside the frame.
  const Placement smaller = place(100, 200, 128, 64);
  EXPECT_LT(smaller.zoom, 1);
  EXPECT_EQ(smaller.width, 100 - 2 * kFrame);
  EXPECT_TRUE(place(2 * kFrame, 50, 128, 128).empty()) << "no room inside the frame";
  EXPECT_TRUE(place(100, 100, 0, 0).empty()) << "nothing to show";
}

TEST(ViewerPresent, AWholeZoomRepeatsEachPixel) {
  const DisplayImage image{2, 1, {10, 20, 30, 40, 50, 60}};
  const DisplayImage same = scaled(image, place(2 + 2 * kFrame, 1 + 2 * kFrame, 2, 1));
  EXPECT_EQ(same.rgb, image.rgb);
  const Placement twice = place(4 + 2 * kFrame, 2 + 2 * kFrame, 2, 1);
  ASSERT_EQ(twice.zoom, 2);
  const DisplayImage big = scaled(image, twice);
  ASSERT_EQ(big.width, 4);
  ASSERT_EQ(big.height, 2);
  const std::vector<uint8_t> row{10, 20, 30, 10, 20, 30, 40, 50, 60, 40, 50, 60};
  EXPECT_EQ(std::vector<uint8_t>(big.rgb.begin(), big.rgb.begin() + 12), row);
  EXPECT_EQ(std::vector<uint8_t>(big.rgb.begin() + 12, big.rgb.end()), row);
}

// The inspector's cursor: the window pixel back to the image pixel it shows, at any zoom,
// and in the split view to the same pixel of the cell whichever panel it is over.
TEST(ViewerPresent, TheCursorMapsBackToTheImagePixelItShows) {
  const Placement exact = place(128 + 2 * kFrame, 128 + 2 * kFrame, 128, 128);
  EXPECT_EQ(pixel_at(exact, kFrame + 0.5, kFrame + 0.5), std::pair(0, 0));
  EXPECT_EQ(pixel_at(exact, kFrame + 40.7, kFrame + 99.2), std::pair(40, 99)) << "row 0 at the top";
  EXPECT_FALSE(pixel_at(exact, 1, 50)) << "on the frame";
  EXPECT_FALSE(pixel_at(exact, kFrame + 128, 50));
  const Placement twice = place(4 + 2 * kFrame, 2 + 2 * kFrame, 2, 1);   // each image pixel 2x2
  EXPECT_EQ(pixel_at(twice, twice.x + 1.5, twice.y + 1.5), std::pair(0, 0));
  EXPECT_EQ(pixel_at(twice, twice.x + 2.5, twice.y + 0.5), std::pair(1, 0));
  // Every window pixel maps to the image pixel scaled() puts there.
  const Placement smaller = place(100, 200, 128, 64);
  for (int x = 0; x < smaller.width; x += 7) {
    const auto at = pixel_at(smaller, smaller.x + x + 0.5, smaller.y + 0.5);
    ASSERT_TRUE(at);
    EXPECT_EQ(at->first, std::min(int((x + 0.5) / smaller.zoom), 127));
  }
  // Split view: render | reference | error, kSplitGap apart; each panel is the same pixels.
  EXPECT_EQ(panel_pixel(10, 20, 64, 64, 1), std::pair(10, 20));
  EXPECT_EQ(panel_pixel(64 + kSplitGap + 10, 20, 64, 64, 3), std::pair(10, 20));
  EXPECT_EQ(panel_pixel(2 * (64 + kSplitGap) + 63, 63, 64, 64, 3), std::pair(63, 63));
  EXPECT_FALSE(panel_pixel(64, 20, 64, 64, 3)) << "in the gap";
  EXPECT_FALSE(panel_pixel(64 + 5, 20, 64, 64, 1)) << "beside a single panel";
  EXPECT_FALSE(panel_pixel(10, 64, 64, 64, 3));
}

}  // namespace
}  // namespace shaderbed::viewer
