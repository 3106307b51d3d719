#include "viewer/GlPresenter.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <type_traits>

#include "viewer/GlfwLibrary.h"

namespace shaderbed::viewer {

// The few GL 1.x calls the window makes, from the window's own context.
struct GlPresenter::Calls {
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
  decltype(&glGetString) get_string = nullptr;

  bool load(const GlfwLibrary& glfw) {
    const auto get = [&](auto& fn, const char* name) {
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(glfw.get_proc_address(name));
      return fn != nullptr;
    };
    return get(viewport, "glViewport") && get(clear_color, "glClearColor") && get(clear, "glClear") &&
           get(pixel_store, "glPixelStorei") && get(pixel_zoom, "glPixelZoom") && get(draw_pixels, "glDrawPixels") &&
           get(window_pos, "glWindowPos2i") && get(read_buffer, "glReadBuffer") && get(read_pixels, "glReadPixels") &&
           get(finish, "glFinish") && get(get_string, "glGetString");
  }
};

GlPresenter::GlPresenter(const GlfwLibrary& glfw, GLFWwindow* window)
    : glfw_(glfw), window_(window), gl_(std::make_unique<Calls>()) {}

GlPresenter::~GlPresenter() = default;

Result<std::unique_ptr<GlPresenter>> GlPresenter::create(const GlfwLibrary& glfw, GLFWwindow* window) {
  std::unique_ptr<GlPresenter> self(new GlPresenter(glfw, window));
  glfw.make_context_current(window);
  if (!self->gl_->load(glfw))
    return fail(ErrorStage::display, "the window's GL context lacks glDrawPixels or glWindowPos2i (GL 1.4)");
  glfw.swap_interval(0);   // frames are drawn on change only; never wait for a vertical blank
  const auto* renderer = reinterpret_cast<const char*>(self->gl_->get_string(GL_RENDERER));
  self->renderer_ = renderer ? renderer : "unknown renderer";
  return self;
}

std::string GlPresenter::description() const { return "the window's GL context (" + renderer_ + ", glDrawPixels)"; }

Result<void> GlPresenter::present(const DisplayImage& image, bool alert, DisplayImage* capture) {
  const Calls& gl = *gl_;
  int fb_width = 0, fb_height = 0;
  glfw_.get_framebuffer_size(window_, &fb_width, &fb_height);
  gl.viewport(0, 0, fb_width, fb_height);
  if (alert) gl.clear_color(kAlertRgb[0] / 255.0f, kAlertRgb[1] / 255.0f, kAlertRgb[2] / 255.0f, 1.0f);
  else gl.clear_color(0.0f, 0.0f, 0.0f, 1.0f);
  gl.clear(GL_COLOR_BUFFER_BIT);
  if (const Placement p = place(fb_width, fb_height, image.width, image.height); !p.empty()) {
    const int bottom = fb_height - p.y - p.height;   // GL's window rows count from the bottom
    gl.pixel_store(GL_UNPACK_ALIGNMENT, 1);
    // Rows come top first: start at the top edge and draw downwards.
    gl.window_pos(p.x, bottom + p.height);
    gl.pixel_zoom(float(p.zoom), -float(p.zoom));
    gl.draw_pixels(image.width, image.height, GL_RGB, GL_UNSIGNED_BYTE, image.rgb.data());
    if (capture) {
      // What was drawn, from the back buffer before the swap: the image's rectangle.
      gl.finish();
      gl.read_buffer(GL_BACK);
      gl.pixel_store(GL_PACK_ALIGNMENT, 1);
      const int w = p.width, h = p.height;
      DisplayImage bottom_up{w, h, std::vector<uint8_t>(size_t(w) * h * 3)};
      gl.read_pixels(p.x, bottom, w, h, GL_RGB, GL_UNSIGNED_BYTE, bottom_up.rgb.data());
      *capture = {w, h, std::vector<uint8_t>(bottom_up.rgb.size())};
      for (int y = 0; y < h; ++y)
        std::copy_n(&bottom_up.rgb[size_t(h - 1 - y) * w * 3], size_t(w) * 3, &capture->rgb[size_t(y) * w * 3]);
    }
  }
  glfw_.swap_buffers(window_);
  return {};
}

}  // namespace shaderbed::viewer
