#pragma once
// GLFW, opened on the viewer's first use rather than linked: libglfw pulls in libX11 and
// libxcb, which every other command (--help, eval, merge, run) would otherwise load at
// start-up. The same reason the GL backend dlopens libOSMesa and image files go through a
// module. Only the functions the viewer calls are looked up.
#include <string>

// Vulkan's header first: GLFW declares its surface functions only when it has been seen.
#include <vulkan/vulkan.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/Error.h"

namespace shaderbed::viewer {

struct GlfwLibrary {
  decltype(&glfwInit) init = nullptr;
  decltype(&glfwTerminate) terminate = nullptr;
  decltype(&glfwSetErrorCallback) set_error_callback = nullptr;
  decltype(&glfwWindowHint) window_hint = nullptr;
  decltype(&glfwCreateWindow) create_window = nullptr;
  decltype(&glfwDestroyWindow) destroy_window = nullptr;
  decltype(&glfwMakeContextCurrent) make_context_current = nullptr;
  decltype(&glfwSwapInterval) swap_interval = nullptr;
  decltype(&glfwSwapBuffers) swap_buffers = nullptr;
  decltype(&glfwWaitEventsTimeout) wait_events_timeout = nullptr;
  decltype(&glfwPostEmptyEvent) post_empty_event = nullptr;
  decltype(&glfwWindowShouldClose) window_should_close = nullptr;
  decltype(&glfwSetWindowShouldClose) set_window_should_close = nullptr;
  decltype(&glfwSetWindowTitle) set_window_title = nullptr;
  decltype(&glfwSetWindowSize) set_window_size = nullptr;
  decltype(&glfwGetFramebufferSize) get_framebuffer_size = nullptr;
  decltype(&glfwGetWindowSize) get_window_size = nullptr;
  decltype(&glfwSetWindowUserPointer) set_window_user_pointer = nullptr;
  decltype(&glfwGetWindowUserPointer) get_window_user_pointer = nullptr;
  decltype(&glfwSetKeyCallback) set_key_callback = nullptr;
  decltype(&glfwSetCharCallback) set_char_callback = nullptr;
  decltype(&glfwSetMouseButtonCallback) set_mouse_button_callback = nullptr;
  decltype(&glfwSetCursorPosCallback) set_cursor_pos_callback = nullptr;
  decltype(&glfwGetCursorPos) get_cursor_pos = nullptr;
  decltype(&glfwSetScrollCallback) set_scroll_callback = nullptr;
  decltype(&glfwSetWindowRefreshCallback) set_window_refresh_callback = nullptr;
  decltype(&glfwGetProcAddress) get_proc_address = nullptr;
  decltype(&glfwDefaultWindowHints) default_window_hints = nullptr;
  decltype(&glfwGetWindowAttrib) get_window_attrib = nullptr;
  decltype(&glfwGetWindowPos) get_window_pos = nullptr;
  decltype(&glfwSetWindowPos) set_window_pos = nullptr;
  decltype(&glfwShowWindow) show_window = nullptr;
  // The Vulkan window (viewer/VulkanPresenter.h).
  decltype(&glfwVulkanSupported) vulkan_supported = nullptr;
  decltype(&glfwGetRequiredInstanceExtensions) get_required_instance_extensions = nullptr;
  decltype(&glfwCreateWindowSurface) create_window_surface = nullptr;
};

// The library with every function found, or why not (libglfw3 missing, a symbol missing).
Result<const GlfwLibrary*> glfw_library();

}  // namespace shaderbed::viewer
