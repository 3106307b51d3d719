#include "backends/gl/EglLibrary.h"

#include <dlfcn.h>

#include <mutex>
#include <sstream>

#include <fmt/format.h>

namespace shaderbed::gl {

const EglLibrary& egl_library() {
  static EglLibrary library;
  static std::once_flag once;
  std::call_once(once, [] {
    void* handle = ::dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      library.error = std::string("cannot load libEGL.so.1 (Debian: libegl1 and libegl-mesa0): ") + ::dlerror();
      return;
    }
    // Never dlclosed: contexts and their threads live until exit.
    const auto symbol = [&](auto& fn, const char* name) {
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(::dlsym(handle, name));
      if (!fn && library.error.empty()) library.error = std::string("libEGL.so.1 has no ") + name;
    };
    symbol(library.get_proc_address, "eglGetProcAddress");
    symbol(library.get_error, "eglGetError");
    symbol(library.query_string, "eglQueryString");
    symbol(library.initialize, "eglInitialize");
    symbol(library.bind_api, "eglBindAPI");
    symbol(library.query_api, "eglQueryAPI");
    symbol(library.choose_config, "eglChooseConfig");
    symbol(library.create_context, "eglCreateContext");
    symbol(library.destroy_context, "eglDestroyContext");
    symbol(library.make_current, "eglMakeCurrent");
    symbol(library.get_current_context, "eglGetCurrentContext");
    if (!library.error.empty()) return;
    // Client extensions need EGL 1.5 or EGL_EXT_client_extensions; without them this is null.
    if (const char* extensions = library.query_string(EGL_NO_DISPLAY, EGL_EXTENSIONS))
      library.client_extensions = extensions;
    const auto extension = [&](auto& fn, const char* name) {
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(library.get_proc_address(name));
    };
    extension(library.get_platform_display, "eglGetPlatformDisplayEXT");
    extension(library.query_devices, "eglQueryDevicesEXT");
    extension(library.query_device_string, "eglQueryDeviceStringEXT");
  });
  return library;
}

bool has_egl_extension(const std::string& extensions, const std::string& extension) {
  std::istringstream words(extensions);
  for (std::string word; words >> word;)
    if (word == extension) return true;
  return false;
}

std::string egl_error_text(const EglLibrary& egl) {
  const EGLint code = egl.get_error ? egl.get_error() : 0;
  const char* name = "an EGL error";
  switch (code) {
    case EGL_SUCCESS: name = "EGL_SUCCESS"; break;
    case EGL_NOT_INITIALIZED: name = "EGL_NOT_INITIALIZED"; break;
    case EGL_BAD_ACCESS: name = "EGL_BAD_ACCESS"; break;
    case EGL_BAD_ALLOC: name = "EGL_BAD_ALLOC"; break;
    case EGL_BAD_ATTRIBUTE: name = "EGL_BAD_ATTRIBUTE"; break;
    case EGL_BAD_CONFIG: name = "EGL_BAD_CONFIG"; break;
    case EGL_BAD_CONTEXT: name = "EGL_BAD_CONTEXT"; break;
    case EGL_BAD_DISPLAY: name = "EGL_BAD_DISPLAY"; break;
    case EGL_BAD_MATCH: name = "EGL_BAD_MATCH"; break;
    case EGL_BAD_PARAMETER: name = "EGL_BAD_PARAMETER"; break;
    case EGL_BAD_SURFACE: name = "EGL_BAD_SURFACE"; break;
    default: break;
  }
  return fmt::format("{} (0x{:04x})", name, code);
}

}  // namespace shaderbed::gl
