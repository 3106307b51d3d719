#pragma once
// One EGL context with no surface (EGL_KHR_surfaceless_context): on Mesa's surfaceless
// platform (EGL_MESA_platform_surfaceless; no display server, no device chosen) or on one
// EGL device (EGL_EXT_platform_device: a GPU's DRM node, Mesa's software device). What
// each needs is in docs/gl-platforms.md.
#include <memory>
#include <string>

#include "backends/gl/GlContext.h"
#include "core/Error.h"

namespace shaderbed::gl {

class EglContext final : public GlContext {
 public:
  // A context of at least major.minor, current on this thread. `device`: "" for the
  // surfaceless platform, else a --gl-device choice (EglDevices.h).
  static Result<std::unique_ptr<EglContext>> create(const std::string& device, int major, int minor,
                                                    Profile profile = Profile::core);

  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;
  ~EglContext() override;

  Result<void> make_current() const override;
  GlProcLoader proc_loader() const override;
  std::string platform() const override { return platform_; }

 private:
  EglContext() = default;
  void* display_ = nullptr;   // EGLDisplay: initialised once per process, never terminated
  void* context_ = nullptr;   // EGLContext
  std::string platform_;
};

}  // namespace shaderbed::gl
