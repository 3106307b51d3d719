#pragma once
// What `shaderbed sh transfer` prints: the shape's vertices, the rays cast, the time, rays
// per second, where the transfer came from and, if asked, every vertex's coefficients; as
// text or as JSON.
#include <string>

#include <nlohmann/json.hpp>

#include "prt/ShShape.h"
#include "prt/ShTransferRun.h"
#include "sh/Transfer.h"
#include "sh/TransferScene.h"

namespace shaderbed {

// The shape and the transfer's sampling as both JSON reports state them (shape, tessellation,
// slices, ground, kind, grid, samples_per_vertex, seed).
nlohmann::json sh_shape_json(const ShShapeRequest& shape);

// The whole of stdout, final newline included.
std::string sh_transfer_report(const ShShapeRequest& shape, const sh::TransferScene& scene, const sh::TransferOptions& options,
                               const ShTransferRun& run, bool coefficients, bool json);

}  // namespace shaderbed
