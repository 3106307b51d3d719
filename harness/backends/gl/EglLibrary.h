#pragma once
// libEGL, opened on first use like libOSMesa (OsMesaContext.cpp): a run on OSMesa or
// Vulkan only never loads it, and the build needs EGL's headers but no display. With
// libglvnd (Debian's libegl1) the vendor library (Mesa's libEGL_mesa, NVIDIA's, ...) is
// chosen per display. The entry points of extensions are looked up once through
// eglGetProcAddress; they are null when the implementation lacks the extension.
#include <string>

#define EGL_NO_X11   // eglplatform.h must not pull in Xlib: nothing here has a window
#include <EGL/egl.h>
#include <EGL/eglext.h>

namespace shaderbed::gl {

struct EglLibrary {
  PFNEGLGETPROCADDRESSPROC get_proc_address = nullptr;
  PFNEGLGETERRORPROC get_error = nullptr;
  PFNEGLQUERYSTRINGPROC query_string = nullptr;
  PFNEGLQUERYAPIPROC query_api = nullptr;
  PFNEGLINITIALIZEPROC initialize = nullptr;
  PFNEGLBINDAPIPROC bind_api = nullptr;
  PFNEGLCHOOSECONFIGPROC choose_config = nullptr;
  PFNEGLCREATECONTEXTPROC create_context = nullptr;
  PFNEGLDESTROYCONTEXTPROC destroy_context = nullptr;
  PFNEGLMAKECURRENTPROC make_current = nullptr;
  PFNEGLGETCURRENTCONTEXTPROC get_current_context = nullptr;
  // Extensions (EGL_EXT_platform_base, EGL_EXT_device_enumeration, EGL_EXT_device_query).
  PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display = nullptr;
  PFNEGLQUERYDEVICESEXTPROC query_devices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC query_device_string = nullptr;
  std::string client_extensions;   // eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)
  std::string error;               // why it could not be loaded; "" when loaded
};

// The process's libEGL (loaded once); check `error` before using it.
const EglLibrary& egl_library();

// True when a space-separated EGL extension list names `extension`.
bool has_egl_extension(const std::string& extensions, const std::string& extension);

// "EGL_BAD_MATCH (0x3009)": the last EGL error on this thread, for messages.
std::string egl_error_text(const EglLibrary& egl);

}  // namespace shaderbed::gl
