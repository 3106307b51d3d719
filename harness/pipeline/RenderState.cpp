#include "pipeline/RenderState.h"

#include <fmt/format.h>

namespace shaderbed {

std::string describe(const RenderState& s) {
  return fmt::format("cull={} depth_test={} depth_write={} depth_compare={} blend={} src={} dest={} op={} fill={}",
                     int(s.cull), s.depth_test, s.depth_write, int(s.depth_compare), s.blend, int(s.src_blend),
                     int(s.dest_blend), int(s.blend_op), int(s.fill));
}

CompareOp depth_compare_for_one_draw(const RenderState& s) {
  if (!s.depth_test) return CompareOp::always;
  if (s.depth_write) return s.depth_compare;
  // Every fragment's depth (in [0, 1) after clipping) against the cleared 1.0.
  switch (s.depth_compare) {
    case CompareOp::less:
    case CompareOp::less_equal:
    case CompareOp::not_equal:
    case CompareOp::always:
      return CompareOp::always;
    case CompareOp::never:
    case CompareOp::equal:
    case CompareOp::greater:
    case CompareOp::greater_equal:
      return CompareOp::never;
  }
  return CompareOp::always;
}

}  // namespace shaderbed
