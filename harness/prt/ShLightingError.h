#pragma once
// `shaderbed sh eval`: for each band count, the error of per-vertex SH lighting (Σ T_i L_i
// in double, the jittered transfer and the light's coefficients) against the exact lighting
// integral at the shape's vertices, with the same visibility.
#include <expected>
#include <memory>
#include <string>
#include <vector>

#include "prt/ShLight.h"
#include "prt/ShShape.h"
#include "sh/Transfer.h"
#include "sh/TransferScene.h"

namespace shaderbed {

struct ShLightingErrorRequest {
  ShShapeRequest shape;                     // unshadowed or shadowed (inter-reflected light has no exact reference)
  std::string light = "directional";        // directional, cone, sky or probe
  std::string probe, mapping = "latlong";   // the environment map of `probe`, latlong or angular
  std::vector<double> direction{0, 1, 0};   // toward the directional or cone light, in the scene (y up)
  double radius = 0.6;                      // the cone's half-angle
  std::vector<int> bands_list;              // band counts to compare ({}: 1 to 8)
  int bands = 0;                            // one band count instead (0: bands_list)
};

// What the comparison needs before the transfer is computed.
struct ShLightingErrorSetup {
  std::unique_ptr<ShLight> light;   // as an SH case's (prt/ShLight.h), not turned
  sh::TransferScene scene;
  sh::TransferOptions options;      // at the largest band count (its prefix serves the others)
  std::vector<int> bands;           // ascending, each once
};

// An error is bad input: inter-reflected transfer, a probe missing or unreadable (naming the
// file), an unknown shape, options sh::check_transfer_options refuses.
std::expected<ShLightingErrorSetup, std::string> prepare_sh_lighting_error(const ShLightingErrorRequest& request);

struct ShLightingError {
  struct Row {
    int bands;
    double max_abs, rms;   // over vertices and channels
    size_t at;             // the vertex of max_abs
  };
  size_t vertices = 0;     // the shape's (not the ground's)
  double exact_seconds = 0, max_exact = 0;   // the exact integral's time, its largest radiance
  std::vector<Row> rows;   // per band count
};

// `transfer`: the shape's (mesh 0); `progress` counts the vertices' exact integrals, which
// run on every core.
ShLightingError measure_sh_lighting_error(const ShLightingErrorSetup& setup, const sh::VertexTransfer& transfer,
                                          const sh::TransferProgress& progress);

}  // namespace shaderbed
