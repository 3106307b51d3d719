#pragma once
// What a GL type enum (from program introspection) looks like as data: scalar kind,
// components per column and columns, or a sampler.
#include <cstdint>

#include <GL/glcorearb.h>

namespace shaderbed::gl {

enum class GlScalarKind { floating, signed_int, unsigned_int, boolean, sampler, unsupported };

struct GlTypeShape {
  GlScalarKind kind = GlScalarKind::unsupported;
  uint32_t vecsize = 1;              // components per column (rows of a matrix)
  uint32_t columns = 1;
  uint32_t sampler_dimensions = 0;   // 1, 2, 3 for samplers
};

GlTypeShape gl_type_shape(GLenum type);

}  // namespace shaderbed::gl
