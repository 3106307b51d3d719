#pragma once
// The fixed-function state of a draw that changes the image: culling, the depth test,
// blending and the fill mode. The defaults are shaderbed's own state (no culling, depth
// test LESS with writes, no blending, solid); a DX9 effect's pass sets the rest
// (compile/EffectFile.h), and both backends apply it.
#include <string>

namespace shaderbed {

// D3D9's meaning: which *on-screen* winding is culled, as the viewer sees the image
// (D3DCULL_CCW, D3D's default, culls counter-clockwise triangles). Under the scene's
// left-handed D3D view, GLUT's outward faces appear clockwise, so `ccw` culls back faces.
enum class CullMode { none, cw, ccw };
enum class FillMode { solid, wireframe, point };
enum class CompareOp { never, less, equal, less_equal, greater, not_equal, greater_equal, always };
enum class BlendFactor {
  zero,
  one,
  src_colour,
  inv_src_colour,
  src_alpha,
  inv_src_alpha,
  dest_alpha,
  inv_dest_alpha,
  dest_colour,
  inv_dest_colour,
  src_alpha_saturate,
};
enum class BlendOp { add, subtract, reverse_subtract, min, max };

struct RenderState {
  CullMode cull = CullMode::none;
  bool depth_test = true;     // ZEnable
  bool depth_write = true;    // ZWriteEnable
  CompareOp depth_compare = CompareOp::less;
  bool blend = false;         // AlphaBlendEnable; the factors apply to colour and alpha alike
  BlendFactor src_blend = BlendFactor::one;
  BlendFactor dest_blend = BlendFactor::zero;
  BlendOp blend_op = BlendOp::add;
  FillMode fill = FillMode::solid;
  bool operator==(const RenderState&) const = default;
};

// "cull=ccw depth=less write=1 blend=0 ..." for pipeline keys and messages.
std::string describe(const RenderState& state);

// The depth compare a backend sets for one draw into a depth buffer cleared to 1, with
// depth writes always on: shaderbed reads coverage from the depth buffer, so a pass
// without the test or without writes must still write depth. For a single draw that is
// exact: with writes off every fragment meets the cleared 1.0, so the test passes all
// fragments or none (`always` or `never`), and with the test off it is `always`.
CompareOp depth_compare_for_one_draw(const RenderState& state);

}  // namespace shaderbed
