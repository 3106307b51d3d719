#pragma once
// The float target every draw lands in: an FBO with a GL_RGBA32F colour texture (so a
// shader's 1.7 or NaN is stored as written) and a GL_DEPTH_COMPONENT32F depth texture
// (whose cleared value 1.0 tells uncovered pixels apart). Read back as a shaderbed::Image
// with row 0 at the top.
#include "backends/gl/GlObject.h"
#include "core/Error.h"
#include "core/Image.h"

namespace shaderbed::gl {

class GlRenderTarget {
 public:
  static Result<GlRenderTarget> create(const GlFunctions& gl, int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }

  // Binds the FBO for drawing and reading, with a full-target viewport.
  void bind() const;

  // Colour as stored, rows flipped (GL reads bottom-up); coverage = depth < 1.
  Result<Image> read_back() const;

 private:
  GlRenderTarget(const GlFunctions& gl, int width, int height) : gl_(&gl), width_(width), height_(height) {}

  const GlFunctions* gl_;
  int width_;
  int height_;
  GlTexture colour_;
  GlTexture depth_;
  GlFramebuffer framebuffer_;
};

}  // namespace shaderbed::gl
