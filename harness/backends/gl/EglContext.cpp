#include "backends/gl/EglContext.h"

#include <cstdlib>

#include "backends/gl/EglDevices.h"
#include "backends/gl/EglLibrary.h"

namespace shaderbed::gl {
namespace {

// Without a chosen device, llvmpipe, as OSMesa and lavapipe draw by default: on a machine
// with a GPU, Mesa's surfaceless platform would take the GPU's driver and every image
// would depend on the machine. LIBGL_ALWAYS_SOFTWARE is Mesa's own switch; a choice the
// user made through it, GALLIUM_DRIVER or MESA_LOADER_DRIVER_OVERRIDE is left alone.
void pin_software_rendering() {
  if (!std::getenv("LIBGL_ALWAYS_SOFTWARE") && !std::getenv("GALLIUM_DRIVER") &&
      !std::getenv("MESA_LOADER_DRIVER_OVERRIDE"))
    ::setenv("LIBGL_ALWAYS_SOFTWARE", "1", /*overwrite=*/0);
}

struct PlatformDisplay {
  EGLDisplay display = EGL_NO_DISPLAY;
  std::string platform;   // as GlContext::platform() says it
};

Result<PlatformDisplay> surfaceless_display(const EglLibrary& egl) {
  if (!egl.get_platform_display || !has_egl_extension(egl.client_extensions, "EGL_MESA_platform_surfaceless"))
    return fail(ErrorStage::gl,
                "this libEGL has no surfaceless platform (EGL_MESA_platform_surfaceless: Mesa's libegl-mesa0); "
                "choose an EGL device with --gl-device ('shaderbed devices' lists them)");
  pin_software_rendering();
  const EGLDisplay display = egl.get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY)
    return fail(ErrorStage::gl,
                "eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA) failed: " + egl_error_text(egl));
  return PlatformDisplay{display, "egl surfaceless"};
}

Result<PlatformDisplay> device_display(const EglLibrary& egl, const std::string& choice) {
  auto device = find_egl_device(choice);
  if (!device) return std::unexpected(device.error());
  if (!egl.get_platform_display || !has_egl_extension(egl.client_extensions, "EGL_EXT_platform_device"))
    return fail(ErrorStage::gl, "this libEGL cannot open a device's display (no EGL_EXT_platform_device)");
  const EGLDisplay display = egl.get_platform_display(EGL_PLATFORM_DEVICE_EXT, device->handle, nullptr);
  if (display == EGL_NO_DISPLAY)
    return fail(ErrorStage::gl, "eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT) failed for EGL device " +
                                    std::to_string(device->index) + " (" + device->name + "): " + egl_error_text(egl));
  return PlatformDisplay{display, "egl device " + std::to_string(device->index) + ": " + device->name};
}

}  // namespace

Result<std::unique_ptr<EglContext>> EglContext::create(const std::string& device, int major, int minor,
                                                       Profile profile) {
  const EglLibrary& egl = egl_library();
  if (!egl.error.empty()) return fail(ErrorStage::gl, egl.error);
  auto platform = device.empty() ? surfaceless_display(egl) : device_display(egl, device);
  if (!platform) return std::unexpected(platform.error());
  const EGLDisplay display = platform->display;
  // Initialising an initialised display only returns its version. Displays are never
  // terminated: eglTerminate would end every context of the display, other renderers' too.
  EGLint egl_major = 0, egl_minor = 0;
  if (!egl.initialize(display, &egl_major, &egl_minor))
    return fail(ErrorStage::gl, "eglInitialize failed on " + platform->platform + ": " + egl_error_text(egl));
  const char* extensions_text = egl.query_string(display, EGL_EXTENSIONS);
  const std::string extensions = extensions_text ? extensions_text : "";
  if (!has_egl_extension(extensions, "EGL_KHR_surfaceless_context"))
    return fail(ErrorStage::gl, platform->platform + " cannot make a context current without a surface "
                                                     "(no EGL_KHR_surfaceless_context)");
  if (!egl.bind_api(EGL_OPENGL_API))
    return fail(ErrorStage::gl, platform->platform + " has no desktop OpenGL (eglBindAPI(EGL_OPENGL_API): " +
                                    egl_error_text(egl) + ")");

  // Without EGL_KHR_no_config_context, any config that renders desktop GL: nothing is ever
  // drawn to a surface of it.
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!has_egl_extension(extensions, "EGL_KHR_no_config_context")) {
    const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
    EGLint found = 0;
    if (!egl.choose_config(display, wanted, &config, 1, &found) || found == 0)
      return fail(ErrorStage::gl, platform->platform + " has no config that renders desktop OpenGL");
  }
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                               major,
                               EGL_CONTEXT_MINOR_VERSION,
                               minor,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               profile == Profile::core ? EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT
                                                        : EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                               EGL_NONE};
  const EGLContext context = egl.create_context(display, config, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT)
    return fail(ErrorStage::gl, platform->platform + " cannot create a " + std::to_string(major) + "." +
                                    std::to_string(minor) +
                                    (profile == Profile::core ? " core" : " compatibility") +
                                    "-profile context: " + egl_error_text(egl));
  std::unique_ptr<EglContext> created(new EglContext());
  created->display_ = display;
  created->context_ = context;
  created->platform_ = platform->platform;
  if (auto current = created->make_current(); !current) return std::unexpected(current.error());
  return created;
}

EglContext::~EglContext() {
  if (last_made_current() == this) last_made_current() = nullptr;
  if (!context_) return;
  const EglLibrary& egl = egl_library();
  egl.bind_api(EGL_OPENGL_API);
  // A context current on this thread would only be deleted once released.
  if (egl.get_current_context() == context_)
    egl.make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  egl.destroy_context(display_, context_);
}

Result<void> EglContext::make_current() const {
  const EglLibrary& egl = egl_library();
  // The bound API is per thread, and eglGetCurrentContext answers for it: this thread may
  // not be the one that created the context (the viewer draws on its own thread).
  egl.bind_api(EGL_OPENGL_API);
  if (egl.get_current_context() == context_) {
    if (last_made_current() == this) return {};
    // EGL would take making it current again as nothing to do, leaving GL's dispatch on
    // the OSMesa context made current since: release it first.
    egl.make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  if (!egl.make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
    return fail(ErrorStage::gl, "eglMakeCurrent failed on " + platform_ + ": " + egl_error_text(egl));
  last_made_current() = this;
  return {};
}

GlProcLoader EglContext::proc_loader() const {
  // EGL 1.5 (and EGL_KHR_get_all_proc_addresses) looks up core GL functions too.
  return [](const char* name) -> GlProc { return reinterpret_cast<GlProc>(egl_library().get_proc_address(name)); };
}

}  // namespace shaderbed::gl
