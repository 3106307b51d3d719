#include "backends/gl/GlRenderState.h"

namespace shaderbed::gl {
namespace {

GLenum to_gl(CompareOp op) {
  switch (op) {
    case CompareOp::never: return GL_NEVER;
    case CompareOp::less: return GL_LESS;
    case CompareOp::equal: return GL_EQUAL;
    case CompareOp::less_equal: return GL_LEQUAL;
    case CompareOp::greater: return GL_GREATER;
    case CompareOp::not_equal: return GL_NOTEQUAL;
    case CompareOp::greater_equal: return GL_GEQUAL;
    case CompareOp::always: return GL_ALWAYS;
  }
  return GL_LESS;
}

GLenum to_gl(BlendFactor f) {
  switch (f) {
    case BlendFactor::zero: return GL_ZERO;
    case BlendFactor::one: return GL_ONE;
    case BlendFactor::src_colour: return GL_SRC_COLOR;
    case BlendFactor::inv_src_colour: return GL_ONE_MINUS_SRC_COLOR;
    case BlendFactor::src_alpha: return GL_SRC_ALPHA;
    case BlendFactor::inv_src_alpha: return GL_ONE_MINUS_SRC_ALPHA;
    case BlendFactor::dest_alpha: return GL_DST_ALPHA;
    case BlendFactor::inv_dest_alpha: return GL_ONE_MINUS_DST_ALPHA;
    case BlendFactor::dest_colour: return GL_DST_COLOR;
    case BlendFactor::inv_dest_colour: return GL_ONE_MINUS_DST_COLOR;
    case BlendFactor::src_alpha_saturate: return GL_SRC_ALPHA_SATURATE;
  }
  return GL_ONE;
}

GLenum to_gl(BlendOp op) {
  switch (op) {
    case BlendOp::add: return GL_FUNC_ADD;
    case BlendOp::subtract: return GL_FUNC_SUBTRACT;
    case BlendOp::reverse_subtract: return GL_FUNC_REVERSE_SUBTRACT;
    case BlendOp::min: return GL_MIN;
    case BlendOp::max: return GL_MAX;
  }
  return GL_FUNC_ADD;
}

}  // namespace

void apply_render_state(const GlFunctions& gl, const RenderState& state) {
  // D3D's CullMode names the winding culled as the image is seen. GL's window origin is
  // lower left here (the readback flips rows), so GL_CW is clockwise as seen too.
  if (state.cull == CullMode::none) {
    gl.Disable(GL_CULL_FACE);
  } else {
    gl.Enable(GL_CULL_FACE);
    gl.FrontFace(GL_CW);
    gl.CullFace(state.cull == CullMode::ccw ? GL_BACK : GL_FRONT);
  }
  // Depth is always written: coverage is read from it (RenderState.h).
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthMask(GL_TRUE);
  gl.DepthFunc(to_gl(depth_compare_for_one_draw(state)));
  if (state.blend) {
    gl.Enable(GL_BLEND);
    gl.BlendFunc(to_gl(state.src_blend), to_gl(state.dest_blend));
    gl.BlendEquation(to_gl(state.blend_op));
  } else {
    gl.Disable(GL_BLEND);
  }
  gl.PolygonMode(GL_FRONT_AND_BACK, state.fill == FillMode::wireframe ? GL_LINE
                                    : state.fill == FillMode::point   ? GL_POINT
                                                                      : GL_FILL);
}

}  // namespace shaderbed::gl
