#pragma once
// One OSMesa context (core profile; compatibility for GL-era GLSL). It renders only into
// FBOs, so the buffer it is made current on is a tiny dummy that is never read. This is
// the only file that includes osmesa.h: its GL/gl.h and glcorearb.h do not mix. Mesa
// removed OSMesa in 25.1; EglContext reaches GL there (docs/gl-platforms.md).
#include <memory>

#include "backends/gl/GlContext.h"
#include "core/Error.h"

namespace shaderbed::gl {

class OsMesaContext final : public GlContext {
 public:
  // A context of at least major.minor (core profile unless asked), current on this thread.
  static Result<OsMesaContext> create(int major, int minor, Profile profile = Profile::core);

  OsMesaContext(OsMesaContext&&) noexcept;
  OsMesaContext& operator=(OsMesaContext&&) noexcept;
  ~OsMesaContext() override;

  Result<void> make_current() const override;
  GlProcLoader proc_loader() const override;
  std::string platform() const override { return "osmesa"; }

 private:
  struct Handle;
  explicit OsMesaContext(std::unique_ptr<Handle>);
  std::unique_ptr<Handle> handle_;
};

}  // namespace shaderbed::gl
