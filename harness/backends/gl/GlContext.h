#pragma once
// A GL context the renderer draws with, however the process reached GL (GlPlatform.h):
// OSMesa (OsMesaContext) or EGL (EglContext). The renderer draws only into its own FBOs,
// so a context needs no window and no default framebuffer of use.
#include <string>

#include "backends/gl/GlFunctions.h"
#include "core/Error.h"

namespace shaderbed::gl {

class GlContext {
 public:
  enum class Profile { core, compatibility };   // compatibility: GL-era GLSL (GlFixedFunctionState.h)

  virtual ~GlContext() = default;

  // Contexts are current per thread: call before issuing GL on the current thread.
  virtual Result<void> make_current() const = 0;
  // Looks GL functions up for this context (the entries are valid while it is current).
  virtual GlProcLoader proc_loader() const = 0;
  // How GL was reached, as the results record it: "osmesa", "egl surfaceless", "egl device 0: software".
  virtual std::string platform() const = 0;

 protected:
  // The context this thread made current last, of either platform. Both drive the same
  // Mesa GL dispatch, so an EGL context EGL still calls current is not GL's current one
  // once an OSMesa context was made current since (a process drawing on both). Cleared
  // by the destructors, so a new context at a freed one's address is not taken for it.
  static const GlContext*& last_made_current() {
    static thread_local const GlContext* context = nullptr;
    return context;
  }
};

}  // namespace shaderbed::gl
