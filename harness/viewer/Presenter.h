#pragma once
// How the viewer's window puts its 8-bit image on screen: through the window's own GL
// context (viewer/GlPresenter.h) for the GL backend's frames, through a Vulkan swapchain
// (viewer/VulkanPresenter.h) for the Vulkan backend's: each backend's frames through its own API. Both show the
// same bytes at the same place: the image scaled to fit inside a frame (black, red while
// the image is not the current state's), centred, each image pixel a whole number of
// window pixels when it fits at 1:1 or more; and both read back what they present.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "core/Error.h"
#include "viewer/SplitView.h"

namespace shaderbed::viewer {

enum class PresentApi { gl, vulkan };

// What presents a backend's frames: Vulkan's through a swapchain, everything else through GL.
PresentApi present_api_of(const std::string& backend);
const char* api_name(PresentApi api);

constexpr int kFrame = 4;   // window pixels of frame around the image
// The frame's red (8-bit sRGB, as both APIs write it); otherwise it is black.
constexpr std::array<uint8_t, 3> kAlertRgb{140, 13, 13};

// Where the image goes in a framebuffer fb_width x fb_height; y counts from the top.
struct Placement {
  int x = 0, y = 0, width = 0, height = 0;
  double zoom = 1;
  bool empty() const { return width <= 0 || height <= 0; }
};
Placement place(int fb_width, int fb_height, int image_width, int image_height);

// The image pixel under framebuffer position (fb_x, fb_y) (y from the top), the inverse of
// `scaled`; none outside the placed image.
std::optional<std::pair<int, int>> pixel_at(const Placement& placement, double fb_x, double fb_y);

// `image` at the placement's size, each window pixel the image pixel under its centre
// (at a whole zoom, each image pixel repeated zoom x zoom times: what glPixelZoom draws).
DisplayImage scaled(const DisplayImage& image, const Placement& placement);

class Presenter {
 public:
  virtual ~Presenter() = default;
  // Shows `image` (none: the frame alone) in the frame, red when `alert`; with `capture`,
  // also reads back the image's rectangle as presented (empty when it cannot).
  virtual Result<void> present(const DisplayImage& image, bool alert, DisplayImage* capture) = 0;
  // How, for the viewer's stderr: "a Vulkan swapchain (lavapipe, VK_KHR_xcb_surface, ...)".
  virtual std::string description() const = 0;
};

}  // namespace shaderbed::viewer
