#include "viewer/ViewerWindow.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <mutex>

#include "viewer/GlfwLibrary.h"

namespace shaderbed::viewer {
namespace {

// GLFW reports errors through a callback; the last one explains a failed call.
std::mutex error_mutex;
std::string last_glfw_error;

void record_error(int, const char* description) {
  const std::lock_guard lock(error_mutex);
  last_glfw_error = description ? description : "unknown GLFW error";
}

std::string take_error() {
  const std::lock_guard lock(error_mutex);
  return std::exchange(last_glfw_error, std::string());
}

// The few GL 1.x calls the window makes, from the window's own context.
struct GlCalls {
  decltype(&glViewport) viewport = nullptr;
  decltype(&glClearColor) clear_color = nullptr;
  decltype(&glClear) clear = nullptr;
  decltype(&glPixelStorei) pixel_store = nullptr;
  decltype(&glPixelZoom) pixel_zoom = nullptr;
  decltype(&glDrawPixels) draw_pixels = nullptr;
  PFNGLWINDOWPOS2IPROC window_pos = nullptr;
  decltype(&glReadBuffer) read_buffer = nullptr;
  decltype(&glReadPixels) read_pixels = nullptr;
  decltype(&glFinish) finish = nullptr;

  bool load(const GlfwLibrary& glfw) {
    const auto get = [&](auto& fn, const char* name) {
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(glfw.get_proc_address(name));
      return fn != nullptr;
    };
    return get(viewport, "glViewport") && get(clear_color, "glClearColor") && get(clear, "glClear") &&
           get(pixel_store, "glPixelStorei") && get(pixel_zoom, "glPixelZoom") && get(draw_pixels, "glDrawPixels") &&
           get(window_pos, "glWindowPos2i") && get(read_buffer, "glReadBuffer") && get(read_pixels, "glReadPixels") &&
           get(finish, "glFinish");
  }
};

std::optional<NamedKey> named_key(int key) {
  switch (key) {
    case GLFW_KEY_TAB: return NamedKey::tab;
    case GLFW_KEY_ESCAPE: return NamedKey::escape;
    case GLFW_KEY_LEFT: return NamedKey::left;
    case GLFW_KEY_RIGHT: return NamedKey::right;
    case GLFW_KEY_UP: return NamedKey::up;
    case GLFW_KEY_DOWN: return NamedKey::down;
    case GLFW_KEY_F1: return NamedKey::f1;
    default: return std::nullopt;
  }
}

// The frame around the image: black, red while the shown image is not the current state's
// (a compile error, say).
constexpr int kFrame = 4;

}  // namespace

struct ViewerWindow::Impl {
  const GlfwLibrary* glfw = nullptr;
  GLFWwindow* window = nullptr;
  GlCalls gl;
  std::mutex events_mutex;
  std::vector<InputEvent> events;
  DisplayImage shown;
  bool alert = false;
  bool dragging = false;
  double last_x = 0, last_y = 0;

  void push(InputEvent e) {
    const std::lock_guard lock(events_mutex);
    // A drag is one event until something else happens: the light turns once per frame.
    if (e.kind == InputEvent::Kind::drag && !events.empty() && events.back().kind == InputEvent::Kind::drag) {
      events.back().dx += e.dx;
      events.back().dy += e.dy;
      return;
    }
    events.push_back(e);
  }

  static Impl& of(GLFWwindow* w) {
    const GlfwLibrary& glfw = **glfw_library();
    return *static_cast<Impl*>(glfw.get_window_user_pointer(w));
  }

  // Draws the image into the back buffer; with `capture`, reads back what was drawn (the
  // image's rectangle, as the window shows it) before the buffers are swapped.
  void draw(DisplayImage* capture = nullptr) {
    int fb_width = 0, fb_height = 0;
    glfw->get_framebuffer_size(window, &fb_width, &fb_height);
    gl.viewport(0, 0, fb_width, fb_height);
    if (alert) gl.clear_color(0.55f, 0.05f, 0.05f, 1.0f);
    else gl.clear_color(0.0f, 0.0f, 0.0f, 1.0f);
    gl.clear(GL_COLOR_BUFFER_BIT);
    const int room_width = fb_width - 2 * kFrame, room_height = fb_height - 2 * kFrame;
    if (shown.width > 0 && shown.height > 0 && room_width > 0 && room_height > 0) {
      // Scaled to fit inside the frame, centred; whole pixels when it fits at 1:1 or more.
      double zoom = std::min(double(room_width) / shown.width, double(room_height) / shown.height);
      if (zoom >= 1) zoom = std::floor(zoom);
      const int w = int(std::lround(shown.width * zoom)), h = int(std::lround(shown.height * zoom));
      const int x0 = (fb_width - w) / 2, y0 = (fb_height - h) / 2;
      gl.pixel_store(GL_UNPACK_ALIGNMENT, 1);
      // Rows come top first: start at the top edge and draw downwards.
      gl.window_pos(x0, y0 + h);
      gl.pixel_zoom(float(zoom), -float(zoom));
      gl.draw_pixels(shown.width, shown.height, GL_RGB, GL_UNSIGNED_BYTE, shown.rgb.data());
      if (capture) {
        gl.finish();
        gl.read_buffer(GL_BACK);
        gl.pixel_store(GL_PACK_ALIGNMENT, 1);
        DisplayImage bottom_up{w, h, std::vector<uint8_t>(size_t(w) * h * 3)};
        gl.read_pixels(x0, y0, w, h, GL_RGB, GL_UNSIGNED_BYTE, bottom_up.rgb.data());
        *capture = {w, h, std::vector<uint8_t>(bottom_up.rgb.size())};
        for (int y = 0; y < h; ++y)
          std::copy_n(&bottom_up.rgb[size_t(h - 1 - y) * w * 3], size_t(w) * 3, &capture->rgb[size_t(y) * w * 3]);
      }
    }
    glfw->swap_buffers(window);
  }
};

ViewerWindow::ViewerWindow(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

ViewerWindow::~ViewerWindow() {
  if (!impl_) return;
  if (impl_->window) impl_->glfw->destroy_window(impl_->window);
  impl_->glfw->terminate();
}

Result<std::unique_ptr<ViewerWindow>> ViewerWindow::open(int width, int height, const std::string& title) {
  auto library = glfw_library();
  if (!library) return std::unexpected(library.error());
  const GlfwLibrary& glfw = **library;
  glfw.set_error_callback(record_error);
  if (!glfw.init())
    return std::unexpected(Error{.message = "no display to open a window on (" + take_error() + ")", .stage = "display"});
  auto impl = std::make_unique<Impl>();
  impl->glfw = &glfw;
  glfw.window_hint(GLFW_RESIZABLE, GLFW_TRUE);
  glfw.window_hint(GLFW_DOUBLEBUFFER, GLFW_TRUE);
  impl->window = glfw.create_window(width + 2 * kFrame, height + 2 * kFrame, title.c_str(), nullptr, nullptr);
  if (!impl->window) {
    const std::string why = take_error();
    glfw.terminate();
    return fail("display", "cannot open a window with a GL context: " + why);
  }
  glfw.make_context_current(impl->window);
  if (!impl->gl.load(glfw)) {
    glfw.destroy_window(impl->window);
    glfw.terminate();
    return fail("display", "the window's GL context lacks glDrawPixels or glWindowPos2i (GL 1.4)");
  }
  glfw.swap_interval(0);   // frames are drawn on change only; never wait for a vertical blank
  glfw.set_window_user_pointer(impl->window, impl.get());
  glfw.set_char_callback(impl->window, [](GLFWwindow* w, unsigned int codepoint) {
    Impl::of(w).push({.kind = InputEvent::Kind::key, .key = KeyPress::typed(char32_t(codepoint))});
  });
  glfw.set_key_callback(impl->window, [](GLFWwindow* w, int key, int, int action, int mods) {
    if (action == GLFW_RELEASE) return;
    if (const auto named = named_key(key))
      Impl::of(w).push({.kind = InputEvent::Kind::key, .key = KeyPress::key(*named, (mods & GLFW_MOD_SHIFT) != 0)});
  });
  glfw.set_mouse_button_callback(impl->window, [](GLFWwindow* w, int button, int action, int) {
    if (button == GLFW_MOUSE_BUTTON_LEFT) Impl::of(w).dragging = action == GLFW_PRESS;
  });
  glfw.set_cursor_pos_callback(impl->window, [](GLFWwindow* w, double x, double y) {
    Impl& self = Impl::of(w);
    if (self.dragging) self.push({.kind = InputEvent::Kind::drag, .dx = x - self.last_x, .dy = y - self.last_y});
    self.last_x = x, self.last_y = y;
  });
  glfw.set_scroll_callback(impl->window, [](GLFWwindow* w, double, double y) {
    Impl::of(w).push({.kind = InputEvent::Kind::scroll, .steps = y});
  });
  // Exposed or resized: show the same pixels again (no new frame is drawn for it).
  glfw.set_window_refresh_callback(impl->window, [](GLFWwindow* w) { Impl::of(w).draw(); });
  impl->draw();
  return std::unique_ptr<ViewerWindow>(new ViewerWindow(std::move(impl)));
}

void ViewerWindow::set_title(const std::string& title) { impl_->glfw->set_window_title(impl_->window, title.c_str()); }

void ViewerWindow::resize(int width, int height) {
  impl_->glfw->set_window_size(impl_->window, width + 2 * kFrame, height + 2 * kFrame);
}

void ViewerWindow::show(const DisplayImage& image, bool alert) {
  impl_->shown = image;
  impl_->alert = alert;
  impl_->draw();
}

DisplayImage ViewerWindow::capture() {
  DisplayImage image;
  impl_->draw(&image);
  return image;
}

void ViewerWindow::wait(double timeout_s) { impl_->glfw->wait_events_timeout(timeout_s); }

void ViewerWindow::wake() { impl_->glfw->post_empty_event(); }

std::vector<InputEvent> ViewerWindow::take_events() {
  const std::lock_guard lock(impl_->events_mutex);
  return std::exchange(impl_->events, {});
}

bool ViewerWindow::close_requested() const { return impl_->glfw->window_should_close(impl_->window) != 0; }

double ViewerWindow::height() const {
  int w = 0, h = 0;
  impl_->glfw->get_window_size(impl_->window, &w, &h);
  return h;
}

}  // namespace shaderbed::viewer
