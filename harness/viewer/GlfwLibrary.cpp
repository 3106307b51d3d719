#include "viewer/GlfwLibrary.h"

#include <dlfcn.h>

#include <mutex>
#include <type_traits>

namespace shaderbed::viewer {

Result<const GlfwLibrary*> glfw_library() {
  static GlfwLibrary library;
  static std::string error;
  static std::once_flag once;
  std::call_once(once, [] {
    void* handle = ::dlopen("libglfw.so.3", RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      error = std::string("cannot load libglfw.so.3 (Debian: libglfw3): ") + ::dlerror();
      return;
    }
    // Never dlclosed: GLFW keeps X11 state until the process ends.
    const auto symbol = [&](auto& fn, const char* name) {
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(::dlsym(handle, name));
      if (!fn && error.empty()) error = std::string("libglfw.so.3 has no ") + name;
    };
    symbol(library.init, "glfwInit");
    symbol(library.terminate, "glfwTerminate");
    symbol(library.set_error_callback, "glfwSetErrorCallback");
    symbol(library.window_hint, "glfwWindowHint");
    symbol(library.create_window, "glfwCreateWindow");
    symbol(library.destroy_window, "glfwDestroyWindow");
    symbol(library.make_context_current, "glfwMakeContextCurrent");
    symbol(library.swap_interval, "glfwSwapInterval");
    symbol(library.swap_buffers, "glfwSwapBuffers");
    symbol(library.wait_events_timeout, "glfwWaitEventsTimeout");
    symbol(library.post_empty_event, "glfwPostEmptyEvent");
    symbol(library.window_should_close, "glfwWindowShouldClose");
    symbol(library.set_window_should_close, "glfwSetWindowShouldClose");
    symbol(library.set_window_title, "glfwSetWindowTitle");
    symbol(library.set_window_size, "glfwSetWindowSize");
    symbol(library.get_framebuffer_size, "glfwGetFramebufferSize");
    symbol(library.get_window_size, "glfwGetWindowSize");
    symbol(library.set_window_user_pointer, "glfwSetWindowUserPointer");
    symbol(library.get_window_user_pointer, "glfwGetWindowUserPointer");
    symbol(library.set_key_callback, "glfwSetKeyCallback");
    symbol(library.set_char_callback, "glfwSetCharCallback");
    symbol(library.set_mouse_button_callback, "glfwSetMouseButtonCallback");
    symbol(library.set_cursor_pos_callback, "glfwSetCursorPosCallback");
    symbol(library.get_cursor_pos, "glfwGetCursorPos");
    symbol(library.set_scroll_callback, "glfwSetScrollCallback");
    symbol(library.set_window_refresh_callback, "glfwSetWindowRefreshCallback");
    symbol(library.get_proc_address, "glfwGetProcAddress");
    symbol(library.default_window_hints, "glfwDefaultWindowHints");
    symbol(library.get_window_attrib, "glfwGetWindowAttrib");
    symbol(library.get_window_pos, "glfwGetWindowPos");
    symbol(library.set_window_pos, "glfwSetWindowPos");
    symbol(library.show_window, "glfwShowWindow");
    symbol(library.vulkan_supported, "glfwVulkanSupported");
    symbol(library.get_required_instance_extensions, "glfwGetRequiredInstanceExtensions");
    symbol(library.create_window_surface, "glfwCreateWindowSurface");
  });
  if (!error.empty()) return fail(ErrorStage::viewer, error);
  return &library;
}

}  // namespace shaderbed::viewer
