#pragma once
// The viewer's window: GLFW, showing an 8-bit image scaled to fit and collecting the
// keyboard and mouse into a queue the viewer applies in order. It draws nothing itself:
// the cell is drawn offscreen by the engine's backends on another thread and handed over
// as pixels, which the window presents with the API of the backend that drew them
// (viewer/Presenter.h): through its own GL context (Mesa llvmpipe through GLX on X11,
// Xvfb included) for the GL backend, through a Vulkan swapchain (lavapipe,
// VK_KHR_xcb_surface) on a window without a GL context for the Vulkan backend. A GLFW
// window keeps its client API for life, so changing API makes the window again (same
// size, place, title and input queue). Everything here runs on the main thread, except
// wake().
#include <memory>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "core/Error.h"
#include "viewer/KeyMap.h"
#include "viewer/Presenter.h"
#include "viewer/SplitView.h"

struct GLFWwindow;

namespace shaderbed::viewer {

struct InputEvent {
  enum class Kind { key, drag, scroll, inspect } kind = Kind::key;
  KeyPress key;
  double dx = 0, dy = 0;   // drag: window pixels moved with the left button down (y down)
  double steps = 0;        // scroll: wheel steps, positive away from the user
  double x = 0, y = 0;     // key, inspect (a right click): the cursor, in window pixels from the top left
};

class ViewerWindow {
 public:
  // A window for an image of width x height (plus a thin frame), presenting through `api`
  // (through GL when a Vulkan swapchain cannot be made: take_notices() says why). An error
  // with stage "display" when there is no display to open (no X server, DISPLAY unset):
  // the caller says so and how to get one.
  static Result<std::unique_ptr<ViewerWindow>> open(int width, int height, const std::string& title, PresentApi api);
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  // Presents through `api` from now on, making the window again when it presented
  // through the other (Vulkan, once it could not present here, is GL from then on). True
  // when the window was made again; an error when no window could be made at all.
  Result<bool> present_with(PresentApi api);
  PresentApi api() const;
  // What to tell the user since the last call, a line each: how each new window presents
  // ("presenting through a Vulkan swapchain (lavapipe, VK_KHR_xcb_surface, ...)"), and
  // why it does not present through Vulkan or could not present a frame.
  std::vector<std::string> take_notices();

  void set_title(const std::string& title);
  // Room for an image of width x height (the content is scaled to fit whatever the size).
  void resize(int width, int height);
  // Whether the last resize() is still on its way: the window system applies it later.
  // False once the window has the size, or a second after the request in any case (a
  // window manager may give it another).
  bool resizing();
  // Shows `image`, scaled to fit, in a frame that is red when `alert`.
  void show(const DisplayImage& image, bool alert);
  // What the window shows of the image, read back from what it presents (the GL back
  // buffer before the swap; the acquired swapchain image before vkQueuePresentKHR): at
  // 1:1, the image's own pixels; larger when the window was made larger. Empty before
  // anything is shown, or when the swapchain's images cannot be read.
  DisplayImage capture();
  // Waits up to `timeout_s` for input, a wake() or a redraw request, and queues the input.
  void wait(double timeout_s);
  // Ends a wait() from any thread.
  void wake();
  std::vector<InputEvent> take_events();
  bool close_requested() const;
  double height() const;   // in screen pixels, for drags
  // The pixel of a shown image of image_width x image_height under window position (x, y)
  // (an InputEvent's), as the presenters place it (viewer/Presenter.h); none outside it.
  std::optional<std::pair<int, int>> image_pixel(double x, double y, int image_width, int image_height) const;

 private:
  struct Impl;
  explicit ViewerWindow(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace shaderbed::viewer
