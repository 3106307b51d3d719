#include "prt/ShShape.h"

#include <optional>

#include <fmt/format.h>

#include "pipeline/Mesh.h"
#include "prt/ShCase.h"
#include "scene/Primitives.h"

namespace shaderbed {

std::string sh_shape_label(const ShShapeRequest& shape) {
  return fmt::format("{} ({}){}", shape.shape, shape.slices > 0 ? fmt::format("{} slices", shape.slices) : shape.tessellation,
                     shape.ground ? " on a ground plane" : "");
}

std::expected<sh::TransferScene, std::string> make_sh_shape_scene(const ShShapeRequest& shape) {
  std::optional<Mesh> mesh = shape.slices > 0 ? make_shape(shape.shape, shape.slices)
                                              : make_shape(shape.shape, shape.tessellation == "high" ? Tessellation::high
                                                                                                     : Tessellation::low);
  if (!mesh) return std::unexpected(fmt::format("--shape {}: no such shape (sphere, cube, cone, torus)", shape.shape));
  return sh_transfer_scene(*mesh, glm::dvec3(shape.albedo[0], shape.albedo[1], shape.albedo[2]), shape.ground);
}

sh::TransferOptions sh_shape_transfer_options(const ShShapeRequest& shape, int bands) {
  sh::TransferOptions o;
  o.kind = sh_transfer_kind(shape.kind);
  o.bands = bands;
  o.grid = shape.grid;
  o.seed = shape.seed;
  o.bounces = o.kind == sh::TransferKind::interreflected ? shape.bounces : 0;
  return o;
}

}  // namespace shaderbed
