#include "backends/gl/GlFunctions.h"

#include <string>

namespace shaderbed::gl {

Result<GlFunctions> load_gl_functions(GlProcLoader loader) {
  GlFunctions gl;
#define SHADERBED_GL_LOAD(type, member, name)                                            \
  gl.member = reinterpret_cast<type>(loader(name));                                      \
  if (gl.member == nullptr) return fail(ErrorStage::gl, std::string("the GL context does not provide ") + name);
  SHADERBED_GL_FUNCTIONS(SHADERBED_GL_LOAD)
#undef SHADERBED_GL_LOAD
  return gl;
}

}  // namespace shaderbed::gl
