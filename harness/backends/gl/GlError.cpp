#include "backends/gl/GlError.h"

#include <cstdio>

namespace shaderbed::gl {
namespace {

std::string gl_error_name(GLenum code) {
  switch (code) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_CONTEXT_LOST: return "GL_CONTEXT_LOST";
  }
  return "GL error 0x" + [code] {
    char hex[16];
    std::snprintf(hex, sizeof hex, "%04X", code);
    return std::string(hex);
  }();
}

}  // namespace

Error gl_error(std::string message) {
  Error error;
  error.message = std::move(message);
  error.stage = ErrorStage::gl;
  error.backend = "gl";
  return error;
}

std::string drain_gl_errors(const GlFunctions& gl) {
  std::string names;
  // Bounded: a lost context may report the same flag forever.
  for (int i = 0; i < 16; ++i) {
    const GLenum code = gl.GetError();
    if (code == GL_NO_ERROR) break;
    if (!names.empty()) names += ", ";
    names += gl_error_name(code);
  }
  return names;
}

Result<void> check_gl(const GlFunctions& gl, std::string_view what) {
  const std::string names = drain_gl_errors(gl);
  if (names.empty()) return {};
  return std::unexpected(gl_error(std::string(what) + " raised " + names));
}

}  // namespace shaderbed::gl
