#include "backends/gl/GlTypeShape.h"

namespace shaderbed::gl {

GlTypeShape gl_type_shape(GLenum type) {
  using K = GlScalarKind;
  switch (type) {
    case GL_FLOAT: return {K::floating, 1, 1};
    case GL_FLOAT_VEC2: return {K::floating, 2, 1};
    case GL_FLOAT_VEC3: return {K::floating, 3, 1};
    case GL_FLOAT_VEC4: return {K::floating, 4, 1};
    case GL_INT: return {K::signed_int, 1, 1};
    case GL_INT_VEC2: return {K::signed_int, 2, 1};
    case GL_INT_VEC3: return {K::signed_int, 3, 1};
    case GL_INT_VEC4: return {K::signed_int, 4, 1};
    case GL_UNSIGNED_INT: return {K::unsigned_int, 1, 1};
    case GL_UNSIGNED_INT_VEC2: return {K::unsigned_int, 2, 1};
    case GL_UNSIGNED_INT_VEC3: return {K::unsigned_int, 3, 1};
    case GL_UNSIGNED_INT_VEC4: return {K::unsigned_int, 4, 1};
    case GL_BOOL: return {K::boolean, 1, 1};
    case GL_BOOL_VEC2: return {K::boolean, 2, 1};
    case GL_BOOL_VEC3: return {K::boolean, 3, 1};
    case GL_BOOL_VEC4: return {K::boolean, 4, 1};
    // GL_FLOAT_MATCxR: C columns of R components.
    case GL_FLOAT_MAT2: return {K::floating, 2, 2};
    case GL_FLOAT_MAT3: return {K::floating, 3, 3};
    case GL_FLOAT_MAT4: return {K::floating, 4, 4};
    case GL_FLOAT_MAT2x3: return {K::floating, 3, 2};
    case GL_FLOAT_MAT2x4: return {K::floating, 4, 2};
    case GL_FLOAT_MAT3x2: return {K::floating, 2, 3};
    case GL_FLOAT_MAT3x4: return {K::floating, 4, 3};
    case GL_FLOAT_MAT4x2: return {K::floating, 2, 4};
    case GL_FLOAT_MAT4x3: return {K::floating, 3, 4};
    case GL_SAMPLER_1D: case GL_SAMPLER_1D_SHADOW: case GL_SAMPLER_1D_ARRAY: case GL_SAMPLER_1D_ARRAY_SHADOW:
    case GL_INT_SAMPLER_1D: case GL_UNSIGNED_INT_SAMPLER_1D:
      return {K::sampler, 1, 1, 1};
    case GL_SAMPLER_3D: case GL_INT_SAMPLER_3D: case GL_UNSIGNED_INT_SAMPLER_3D:
      return {K::sampler, 1, 1, 3};
    case GL_SAMPLER_2D: case GL_SAMPLER_2D_SHADOW: case GL_SAMPLER_2D_ARRAY: case GL_SAMPLER_2D_ARRAY_SHADOW:
    case GL_SAMPLER_CUBE: case GL_SAMPLER_CUBE_SHADOW: case GL_SAMPLER_2D_RECT: case GL_SAMPLER_2D_RECT_SHADOW:
    case GL_SAMPLER_2D_MULTISAMPLE: case GL_SAMPLER_BUFFER:
    case GL_INT_SAMPLER_2D: case GL_UNSIGNED_INT_SAMPLER_2D: case GL_INT_SAMPLER_CUBE: case GL_UNSIGNED_INT_SAMPLER_CUBE:
      return {K::sampler, 1, 1, 2};
    default: return {};
  }
}

}  // namespace shaderbed::gl
