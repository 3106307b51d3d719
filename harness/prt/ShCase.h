#pragma once
// The spherical-harmonic cases (book Ch. 8 and 9, docs/sh.md). A case names one of the
// SH models; this turns it into what the GPU is given (per-vertex streams, light
// coefficients as uniforms) and into the two CPU references:
//   sh             per-vertex transfer T as vertex inputs, L_o = Σ T_i L_i in the vertex shader
//   sh_cpca        the book's SH_VS (Ch. 9.2.2): cluster offset and PCA weights per vertex,
//                  the per-cluster dot products with the light (Eq. 9.1) as constants
//   sh_irradiance  the 9-coefficient irradiance of the interpolated normal, per pixel
//   sh_specular    sh_irradiance plus a specular cube map looked up at the reflection
//                  vector (book Ch. 9.7), the cube map generated here (prt/ShSpecular.h)
// The verdict's reference is the truncated SH evaluated in double (the shader's own error,
// judged with fp32 tolerances); the exact lighting integral (quadrature or a delta light,
// with the same visibility) is the second reference, whose difference is the
// approximation's error (reported, and bounded by `[tolerance] approximation`).
#include <expected>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/Texture.h"
#include "core/Error.h"
#include "reference/LightingModel.h"
#include "scene/CaseFile.h"
#include "pipeline/Mesh.h"
#include "scene/Scene.h"
#include "sh/Transfer.h"
#include "sh/TransferScene.h"

namespace shaderbed {

bool is_sh_model(std::string_view model);
const std::vector<std::string>& sh_model_names();

// The numeric parameters an SH model reads, with their defaults (docs/sh.md).
std::map<std::string, std::vector<double>> sh_default_params(std::string_view model);

// Gives an SH case the default of every parameter it leaves out.
void apply_sh_defaults(Case& c);

// Whether a parameter chooses how an SH case approximates the scene (bands, rays,
// clusters, ...) rather than what the scene is (its light's rotation, the albedo).
bool is_sh_approximation_parameter(std::string_view name);

struct ShPrepared {
  Mesh mesh;                 // the shape with the case's per-vertex streams
  NamedValues uniforms;      // light coefficients, cluster constants
  // Textures generated for the case, by the binding value that names them
  // ([bindings.<language>] SAMPLER = "sh_specular"): sh_specular's cube map.
  std::map<std::string, std::shared_ptr<const Texture>> textures;
  std::shared_ptr<const reference::LightingModel> truncated;   // SH in double
  std::shared_ptr<const reference::LightingModel> exact;       // null: no exact integral (inter-reflected)
  std::string summary;       // bands, samples, light, where the transfer came from
  double precompute_ms = 0;  // transfer, projection and CPCA (0 when served from the cache)
  size_t bytes_per_vertex = 0;   // what the per-vertex streams cost
};

// The transfer scene an SH case casts its rays into: the shape as mesh 0, of diffuse
// `albedo`, and with `ground` the plane it stands on as mesh 1 (albedo 0.8, 1% of the
// shape's extent below its lowest point, 8 extents wide). Also `shaderbed sh transfer|eval`.
std::expected<sh::TransferScene, std::string> sh_transfer_scene(const Mesh& shape, const glm::dvec3& albedo, bool ground);

// A case's `[sh] transfer` (unshadowed, shadowed, interreflected) as the transfer's kind.
sh::TransferKind sh_transfer_kind(std::string_view name);

// Everything an SH case's group needs for one shape. `cache_dir` "" = no transfer cache.
Result<ShPrepared> prepare_sh(const Case& c, const Mesh& shape, const SceneSetup& scene,
                              const std::filesystem::path& cache_dir);

}  // namespace shaderbed
