#pragma once
// Owns one GL object name and deletes it with the matching glDelete* call, so every
// early error return in the renderer leaves no GL object behind in the long-lived
// context. The context must be current when the owner goes out of scope.
#include <utility>

#include "backends/gl/GlFunctions.h"

namespace shaderbed::gl {

enum class GlObjectKind { buffer, vertex_array, texture, framebuffer, shader, program, query };

template <GlObjectKind kind>
class GlObject {
 public:
  GlObject() = default;
  GlObject(const GlFunctions& gl, GLuint name) : gl_(&gl), name_(name) {}
  GlObject(GlObject&& other) noexcept : gl_(other.gl_), name_(std::exchange(other.name_, 0)) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      reset();
      gl_ = other.gl_;
      name_ = std::exchange(other.name_, 0);
    }
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;
  ~GlObject() { reset(); }

  GLuint get() const { return name_; }
  explicit operator bool() const { return name_ != 0; }

  void reset() {
    if (name_ == 0) return;
    if constexpr (kind == GlObjectKind::buffer) gl_->DeleteBuffers(1, &name_);
    if constexpr (kind == GlObjectKind::vertex_array) gl_->DeleteVertexArrays(1, &name_);
    if constexpr (kind == GlObjectKind::texture) gl_->DeleteTextures(1, &name_);
    if constexpr (kind == GlObjectKind::framebuffer) gl_->DeleteFramebuffers(1, &name_);
    if constexpr (kind == GlObjectKind::shader) gl_->DeleteShader(name_);
    if constexpr (kind == GlObjectKind::program) gl_->DeleteProgram(name_);
    if constexpr (kind == GlObjectKind::query) gl_->DeleteQueries(1, &name_);
    name_ = 0;
  }

 private:
  const GlFunctions* gl_ = nullptr;
  GLuint name_ = 0;
};

using GlBuffer = GlObject<GlObjectKind::buffer>;
using GlVertexArray = GlObject<GlObjectKind::vertex_array>;
using GlTexture = GlObject<GlObjectKind::texture>;
using GlFramebuffer = GlObject<GlObjectKind::framebuffer>;
using GlShader = GlObject<GlObjectKind::shader>;
using GlProgram = GlObject<GlObjectKind::program>;
using GlQuery = GlObject<GlObjectKind::query>;

// glGen* for one object of the kind, owned.
inline GlBuffer make_buffer(const GlFunctions& gl) {
  GLuint name = 0;
  gl.GenBuffers(1, &name);
  return GlBuffer(gl, name);
}
inline GlVertexArray make_vertex_array(const GlFunctions& gl) {
  GLuint name = 0;
  gl.GenVertexArrays(1, &name);
  return GlVertexArray(gl, name);
}
inline GlTexture make_texture(const GlFunctions& gl) {
  GLuint name = 0;
  gl.GenTextures(1, &name);
  return GlTexture(gl, name);
}
inline GlFramebuffer make_framebuffer(const GlFunctions& gl) {
  GLuint name = 0;
  gl.GenFramebuffers(1, &name);
  return GlFramebuffer(gl, name);
}

}  // namespace shaderbed::gl
