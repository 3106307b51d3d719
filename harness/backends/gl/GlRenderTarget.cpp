#include "backends/gl/GlRenderTarget.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "backends/gl/GlError.h"

namespace shaderbed::gl {
namespace {

std::string size_text(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

std::string framebuffer_status_name(GLenum status) {
  switch (status) {
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    default: return "status " + std::to_string(status);
  }
}

}  // namespace

Result<GlRenderTarget> GlRenderTarget::create(const GlFunctions& gl, int width, int height) {
  GLint max_size = 0;
  gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  GLint max_viewport[2] = {0, 0};
  gl.GetIntegerv(GL_MAX_VIEWPORT_DIMS, max_viewport);
  const int limit_x = std::min(max_size, max_viewport[0]), limit_y = std::min(max_size, max_viewport[1]);
  if (width <= 0 || height <= 0 || width > limit_x || height > limit_y)
    return std::unexpected(gl_error("render target " + size_text(width, height) + " is outside 1x1.." +
                                    size_text(limit_x, limit_y)));

  GlRenderTarget target(gl, width, height);
  target.colour_ = make_texture(gl);
  gl.BindTexture(GL_TEXTURE_2D, target.colour_.get());
  gl.TexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, width, height);
  target.depth_ = make_texture(gl);
  gl.BindTexture(GL_TEXTURE_2D, target.depth_.get());
  gl.TexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT32F, width, height);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  if (auto ok = check_gl(gl, "allocating the " + size_text(width, height) + " float target"); !ok)
    return std::unexpected(ok.error());

  target.framebuffer_ = make_framebuffer(gl);
  gl.BindFramebuffer(GL_FRAMEBUFFER, target.framebuffer_.get());
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.colour_.get(), 0);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, target.depth_.get(), 0);
  const GLenum draw_buffer = GL_COLOR_ATTACHMENT0;
  gl.DrawBuffers(1, &draw_buffer);
  gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    return std::unexpected(gl_error("RGBA32F + DEPTH32F framebuffer is incomplete: " + framebuffer_status_name(status)));
  if (auto ok = check_gl(gl, "building the framebuffer"); !ok) return std::unexpected(ok.error());
  return target;
}

void GlRenderTarget::bind() const {
  gl_->BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  gl_->Viewport(0, 0, width_, height_);
}

Result<Image> GlRenderTarget::read_back() const {
  bind();
  // Float colour is never clamped on read; the state is set anyway so a driver whose
  // GL_FIXED_ONLY default misjudges the target cannot clamp 1.7 to 1.
  gl_->ClampColor(GL_CLAMP_READ_COLOR, GL_FALSE);
  gl_->PixelStorei(GL_PACK_ALIGNMENT, 4);
  gl_->PixelStorei(GL_PACK_ROW_LENGTH, 0);
  gl_->PixelStorei(GL_PACK_SKIP_ROWS, 0);
  gl_->PixelStorei(GL_PACK_SKIP_PIXELS, 0);

  const size_t pixels = size_t(width_) * height_;
  std::vector<float> colour(pixels * 4);
  std::vector<float> depth(pixels);
  gl_->ReadBuffer(GL_COLOR_ATTACHMENT0);
  gl_->ReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, colour.data());
  gl_->ReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  if (auto ok = check_gl(*gl_, "reading back the target"); !ok) return std::unexpected(ok.error());

  // GL row 0 is the bottom of the image; shaderbed::Image row 0 is the top.
  Image image(width_, height_);
  const size_t row_floats = size_t(width_) * 4;
  for (int y = 0; y < height_; ++y) {
    const size_t gl_row = size_t(height_ - 1 - y);
    std::memcpy(image.pixel(0, y), colour.data() + gl_row * row_floats, row_floats * sizeof(float));
    for (int x = 0; x < width_; ++x) image.coverage[image.index(x, y)] = depth[gl_row * width_ + x] < 1.0f ? 1 : 0;
  }
  return image;
}

}  // namespace shaderbed::gl
