#pragma once
// The shape `shaderbed sh transfer|eval` compute on: one of the run engine's shapes at a
// case's tessellation or any density, optionally on the ground plane an SH case stands on,
// and the transfer asked of it.
#include <cstdint>
#include <expected>
#include <string>
#include <vector>

#include "sh/Sampling.h"
#include "sh/Transfer.h"
#include "sh/TransferScene.h"

namespace shaderbed {

struct ShShapeRequest {
  std::string shape;                    // sphere, cube, cone or torus
  std::string tessellation = "low";     // low or high, as a case's `tessellation`
  int slices = 0;                       // 0: by tessellation
  bool ground = false;
  std::vector<double> albedo{1, 1, 1};  // r, g, b
  std::string kind = "shadowed";        // unshadowed, shadowed or interreflected
  int bounces = 1;                      // of the inter-reflected transfer
  int grid = 100;                       // grid x grid jittered rays per vertex
  uint64_t seed = sh::default_seed;
  bool no_cache = false;                // compute even if the cache holds it, and do not store it
};

// "sphere (low) on a ground plane", as the reports name the shape.
std::string sh_shape_label(const ShShapeRequest& shape);

// The shape (mesh 0) and its ground (mesh 1) as the transfer casts rays into them; an
// unknown shape is an error naming --shape.
std::expected<sh::TransferScene, std::string> make_sh_shape_scene(const ShShapeRequest& shape);

// The transfer asked for, at `bands` (check it with sh::check_transfer_options).
sh::TransferOptions sh_shape_transfer_options(const ShShapeRequest& shape, int bands);

}  // namespace shaderbed
