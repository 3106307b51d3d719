#include "backends/gl/GlPlatform.h"

#include "backends/gl/EglContext.h"
#include "backends/gl/OsMesaContext.h"

namespace shaderbed {
namespace {

GlPlatformChoice& gl_platform_choice() {
  static GlPlatformChoice choice;
  return choice;
}

}  // namespace

void choose_gl_platform(GlPlatformChoice choice) { gl_platform_choice() = std::move(choice); }
const GlPlatformChoice& chosen_gl_platform() { return gl_platform_choice(); }

namespace gl {

Result<std::unique_ptr<GlContext>> create_gl_context(const GlPlatformChoice& choice, int major, int minor,
                                                     GlContext::Profile profile) {
  if (choice.platform == "egl") {
    auto context = EglContext::create(choice.device, major, minor, profile);
    if (!context) return std::unexpected(context.error());
    return std::unique_ptr<GlContext>(std::move(*context));
  }
  if (choice.platform != "osmesa")
    return fail(ErrorStage::gl, "unknown GL platform '" + choice.platform + "' (osmesa or egl)");
  if (!choice.device.empty())
    return fail(ErrorStage::gl, "OSMesa has no devices: --gl-device needs --gl-platform egl");
  auto context = OsMesaContext::create(major, minor, profile);
  if (!context) return std::unexpected(context.error());
  return std::unique_ptr<GlContext>(std::make_unique<OsMesaContext>(std::move(*context)));
}

}  // namespace gl
}  // namespace shaderbed
