#include "viewer/ViewerWindow.h"

#include <chrono>
#include <mutex>
#include <optional>

#include "core/LeakReportPins.h"
#include "viewer/GlPresenter.h"
#include "viewer/GlfwLibrary.h"
#include "viewer/VulkanPresenter.h"

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

}  // namespace

struct ViewerWindow::Impl {
  const GlfwLibrary* glfw = nullptr;
  GLFWwindow* window = nullptr;
  std::unique_ptr<Presenter> presenter;
  PresentApi api = PresentApi::gl;
  bool vulkan_failed = false;   // Vulkan could not present here: GL from then on
  std::string title;
  std::mutex events_mutex;
  std::vector<InputEvent> events;
  std::vector<std::string> notices;
  std::string present_problem;   // the last frame's, told once
  DisplayImage shown;
  bool alert = false;
  bool dragging = false;
  double last_x = 0, last_y = 0;
  std::optional<std::pair<int, int>> requested_size;   // a resize() not seen on screen yet
  std::chrono::steady_clock::time_point requested_at;

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

  // Shows the image; with `capture`, reads back what was presented (the image's rectangle).
  void draw(DisplayImage* capture = nullptr) {
    if (!presenter) return;
    auto ok = presenter->present(shown, alert, capture);
    if (ok) {
      present_problem.clear();
      return;
    }
    const std::string why = ok.error().to_string();
    if (api == PresentApi::vulkan) {
      // The next present_with() makes a GL window (not here: this may be the window's own callback).
      vulkan_failed = true;
      notices.push_back("cannot present through the Vulkan swapchain: " + why + "; presenting through GL instead");
      return;
    }
    if (why == present_problem) return;
    present_problem = why;
    notices.push_back("cannot present the frame through GL: " + why);
  }

  void destroy() {
    presenter.reset();   // the surface and swapchain before their window
    if (window) glfw->destroy_window(window);
    window = nullptr;
  }

  // A window (width x height screen pixels, at `position` when given) presenting through `with`.
  Result<void> make(PresentApi with, int width, int height, std::optional<std::pair<int, int>> position) {
    glfw->default_window_hints();
    glfw->window_hint(GLFW_RESIZABLE, GLFW_TRUE);
    glfw->window_hint(GLFW_VISIBLE, GLFW_FALSE);   // shown once in place
    if (with == PresentApi::vulkan) {
      glfw->window_hint(GLFW_CLIENT_API, GLFW_NO_API);
    } else {
      glfw->window_hint(GLFW_CLIENT_API, GLFW_OPENGL_API);
      glfw->window_hint(GLFW_DOUBLEBUFFER, GLFW_TRUE);
    }
    take_error();
    window = glfw->create_window(width, height, title.c_str(), nullptr, nullptr);
    if (!window)
      return fail(ErrorStage::display, std::string(with == PresentApi::vulkan ? "cannot open a window for Vulkan: "
                                                                     : "cannot open a window with a GL context: ") +
                                 take_error());
    pin_loaded_libraries_for_leak_reports();   // the GL window's DRI driver, which GLX closes with it
    if (position) glfw->set_window_pos(window, position->first, position->second);
    Result<std::unique_ptr<Presenter>> made = std::unique_ptr<Presenter>();
    if (with == PresentApi::vulkan) {
      auto vulkan = VulkanPresenter::create(*glfw, window);
      if (vulkan) made = std::unique_ptr<Presenter>(std::move(*vulkan));
      else made = std::unexpected(vulkan.error());
    } else {
      auto gl = GlPresenter::create(*glfw, window);
      if (gl) made = std::unique_ptr<Presenter>(std::move(*gl));
      else made = std::unexpected(gl.error());
    }
    if (!made) {
      const std::string glfw_says = take_error();
      Error e = made.error();
      if (!glfw_says.empty()) e.message += " (GLFW: " + glfw_says + ")";
      destroy();
      return std::unexpected(std::move(e));
    }
    presenter = std::move(*made);
    api = with;
    dragging = false;
    present_problem.clear();
    glfw->set_window_user_pointer(window, this);
    glfw->set_char_callback(window, [](GLFWwindow* w, unsigned int codepoint) {
      Impl& self = Impl::of(w);
      double x = 0, y = 0;   // where the cursor is: `i` inspects the pixel under it
      self.glfw->get_cursor_pos(w, &x, &y);
      self.push({.kind = InputEvent::Kind::key, .key = KeyPress::typed(char32_t(codepoint)), .x = x, .y = y});
    });
    glfw->set_key_callback(window, [](GLFWwindow* w, int key, int, int action, int mods) {
      if (action == GLFW_RELEASE) return;
      if (const auto named = named_key(key))
        Impl::of(w).push({.kind = InputEvent::Kind::key, .key = KeyPress::key(*named, (mods & GLFW_MOD_SHIFT) != 0)});
    });
    glfw->set_mouse_button_callback(window, [](GLFWwindow* w, int button, int action, int) {
      Impl& self = Impl::of(w);
      if (button == GLFW_MOUSE_BUTTON_LEFT) self.dragging = action == GLFW_PRESS;
      if (button == GLFW_MOUSE_BUTTON_RIGHT && action == GLFW_PRESS) {   // inspect the pixel clicked
        double x = 0, y = 0;
        self.glfw->get_cursor_pos(w, &x, &y);
        self.push({.kind = InputEvent::Kind::inspect, .x = x, .y = y});
      }
    });
    glfw->set_cursor_pos_callback(window, [](GLFWwindow* w, double x, double y) {
      Impl& self = Impl::of(w);
      if (self.dragging) self.push({.kind = InputEvent::Kind::drag, .dx = x - self.last_x, .dy = y - self.last_y});
      self.last_x = x, self.last_y = y;
    });
    glfw->set_scroll_callback(window, [](GLFWwindow* w, double, double y) {
      Impl::of(w).push({.kind = InputEvent::Kind::scroll, .steps = y});
    });
    // Exposed or resized: show the same pixels again (no new frame is drawn for it).
    glfw->set_window_refresh_callback(window, [](GLFWwindow* w) { Impl::of(w).draw(); });
    glfw->show_window(window);
    notices.push_back("presenting through " + presenter->description());
    return {};
  }

  // make(), and when Vulkan cannot present here, GL instead (and Vulkan no more).
  Result<void> make_or_fall_back(PresentApi with, int width, int height, std::optional<std::pair<int, int>> position) {
    if (with == PresentApi::vulkan && vulkan_failed) with = PresentApi::gl;
    auto made = make(with, width, height, position);
    if (made || with == PresentApi::gl) return made;
    vulkan_failed = true;
    notices.push_back("cannot present through a Vulkan swapchain: " + made.error().to_string() +
                      "; presenting through GL instead");
    return make(PresentApi::gl, width, height, position);
  }

  // Made again for `with`, at the same size and place.
  Result<bool> remake(PresentApi with) {
    if (with == PresentApi::vulkan && vulkan_failed) with = PresentApi::gl;
    if (window && with == api) return false;
    int width = 0, height = 0, x = 0, y = 0;
    glfw->get_window_size(window, &width, &height);
    glfw->get_window_pos(window, &x, &y);
    destroy();
    if (auto made = make_or_fall_back(with, width, height, std::pair{x, y}); !made) return std::unexpected(made.error());
    draw();
    return true;
  }
};

ViewerWindow::ViewerWindow(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

ViewerWindow::~ViewerWindow() {
  if (!impl_) return;
  impl_->destroy();
  impl_->glfw->terminate();
}

Result<std::unique_ptr<ViewerWindow>> ViewerWindow::open(int width, int height, const std::string& title,
                                                         PresentApi api) {
  auto library = glfw_library();
  if (!library) return std::unexpected(library.error());
  const GlfwLibrary& glfw = **library;
  glfw.set_error_callback(record_error);
  if (!glfw.init())
    return std::unexpected(Error{.message = "no display to open a window on (" + take_error() + ")", .stage = ErrorStage::display});
  auto impl = std::make_unique<Impl>();
  impl->glfw = &glfw;
  impl->title = title;
  if (auto made = impl->make_or_fall_back(api, width + 2 * kFrame, height + 2 * kFrame, std::nullopt); !made) {
    glfw.terminate();
    return std::unexpected(made.error());
  }
  impl->draw();
  return std::unique_ptr<ViewerWindow>(new ViewerWindow(std::move(impl)));
}

Result<bool> ViewerWindow::present_with(PresentApi api) { return impl_->remake(api); }

PresentApi ViewerWindow::api() const { return impl_->api; }

std::vector<std::string> ViewerWindow::take_notices() { return std::exchange(impl_->notices, {}); }

void ViewerWindow::set_title(const std::string& title) {
  impl_->title = title;
  impl_->glfw->set_window_title(impl_->window, title.c_str());
}

void ViewerWindow::resize(int width, int height) {
  impl_->requested_size = std::pair(width + 2 * kFrame, height + 2 * kFrame);
  impl_->requested_at = std::chrono::steady_clock::now();
  impl_->glfw->set_window_size(impl_->window, impl_->requested_size->first, impl_->requested_size->second);
}

bool ViewerWindow::resizing() {
  if (!impl_->requested_size) return false;
  std::pair<int, int> now;
  impl_->glfw->get_window_size(impl_->window, &now.first, &now.second);
  if (now == *impl_->requested_size || std::chrono::steady_clock::now() - impl_->requested_at > std::chrono::seconds(1))
    impl_->requested_size.reset();
  return impl_->requested_size.has_value();
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

std::optional<std::pair<int, int>> ViewerWindow::image_pixel(double x, double y, int image_width,
                                                            int image_height) const {
  int w = 0, h = 0, fb_width = 0, fb_height = 0;
  impl_->glfw->get_window_size(impl_->window, &w, &h);
  impl_->glfw->get_framebuffer_size(impl_->window, &fb_width, &fb_height);
  if (w <= 0 || h <= 0) return std::nullopt;
  // Window (screen) coordinates to the framebuffer's, where the presenters place the image.
  return pixel_at(place(fb_width, fb_height, image_width, image_height), x * fb_width / w, y * fb_height / h);
}

}  // namespace shaderbed::viewer
