#pragma once
// The viewer's window: GLFW with its own GL context (Mesa llvmpipe through GLX on X11,
// Xvfb included), which shows an 8-bit image scaled to fit and collects the keyboard and
// mouse into a queue the viewer applies in order. It draws nothing itself: the cell is
// drawn offscreen by the engine's backends on another thread and handed over as pixels.
// Everything here runs on the main thread, except wake().
#include <memory>
#include <string>
#include <vector>

#include "core/Error.h"
#include "viewer/KeyMap.h"
#include "viewer/SplitView.h"

struct GLFWwindow;

namespace shaderbed::viewer {

struct InputEvent {
  enum class Kind { key, drag, scroll } kind = Kind::key;
  KeyPress key;
  double dx = 0, dy = 0;   // drag: window pixels moved with the left button down (y down)
  double steps = 0;        // scroll: wheel steps, positive away from the user
};

class ViewerWindow {
 public:
  // A window for an image of width x height (plus a thin frame). An error with stage
  // "display" when there is no display to open (no X server, DISPLAY unset): the caller
  // says so and how to get one.
  static Result<std::unique_ptr<ViewerWindow>> open(int width, int height, const std::string& title);
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  void set_title(const std::string& title);
  // Room for an image of width x height (the content is scaled to fit whatever the size).
  void resize(int width, int height);
  // Shows `image`, scaled to fit, in a frame that is red when `alert`.
  void show(const DisplayImage& image, bool alert);
  // What the window shows of the image, read back from its GL context (at 1:1, the image's
  // own pixels; larger when the window was made larger). Empty before anything is shown.
  DisplayImage capture();
  // Waits up to `timeout_s` for input, a wake() or a redraw request, and queues the input.
  void wait(double timeout_s);
  // Ends a wait() from any thread.
  void wake();
  std::vector<InputEvent> take_events();
  bool close_requested() const;
  double height() const;   // in screen pixels, for drags

 private:
  struct Impl;
  explicit ViewerWindow(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace shaderbed::viewer
