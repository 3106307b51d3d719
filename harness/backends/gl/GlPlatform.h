#pragma once
// How the GL backend reaches GL (--gl-platform, docs/gl-platforms.md): OSMesa, the
// default (Mesa up to 25.0), or EGL: Mesa's surfaceless platform, or one EGL device
// (--gl-device) such as a GPU's. The process-wide choice is backends/Backend.h's
// chosen_gl_platform(); here, what it names and the contexts made on it.
#include <array>
#include <memory>
#include <string_view>

#include "backends/Backend.h"
#include "backends/gl/GlContext.h"

namespace shaderbed::gl {

inline constexpr std::array<std::string_view, 2> kGlPlatforms = {"osmesa", "egl"};

// A context of at least major.minor on `choice`'s platform, current on this thread.
Result<std::unique_ptr<GlContext>> create_gl_context(const GlPlatformChoice& choice, int major, int minor,
                                                     GlContext::Profile profile);

}  // namespace shaderbed::gl
