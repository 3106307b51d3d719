#include "prt/ShLightingError.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>

#include <tbb/parallel_for.h>

#include "prt/ProbeFile.h"
#include "prt/RgbValues.h"
#include "scene/CaseFile.h"
#include "scene/Scene.h"

namespace shaderbed {

std::expected<ShLightingErrorSetup, std::string> prepare_sh_lighting_error(const ShLightingErrorRequest& a) {
  if (a.shape.kind == "interreflected")
    return std::unexpected("--kind interreflected has no exact reference (its bounces are the approximation itself); "
                           "use unshadowed or shadowed");
  if (a.light == "probe" && a.probe.empty())
    return std::unexpected("--light probe needs --probe FILE (an .hdr or .exr environment map)");
  std::vector<int> bands = a.bands > 0           ? std::vector<int>{a.bands}
                           : a.bands_list.empty() ? std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8}
                                                  : a.bands_list;
  std::ranges::sort(bands);
  const auto [last, end] = std::ranges::unique(bands);
  bands.erase(last, end);

  // The light as an SH case's, not turned.
  ShSetup setup;
  setup.transfer = a.shape.kind;
  setup.light = a.light;
  setup.probe = a.probe.empty() ? "" : std::filesystem::absolute(a.probe).string();
  setup.mapping = a.mapping;
  setup.ground = a.shape.ground;
  Case c;
  c.name = "sh eval";
  c.params["cone_radius"] = {a.radius};
  SceneSetup scene_setup;
  scene_setup.lights.direction = glm::dvec3(a.direction[0], a.direction[1], a.direction[2]);
  auto light = make_sh_light(setup, c, scene_setup, glm::dmat3(1.0));
  if (!light) return std::unexpected(a.light == "probe" ? naming_file(a.probe, light.error().message) : light.error().message);

  auto scene = make_sh_shape_scene(a.shape);
  if (!scene) return std::unexpected(scene.error());
  const sh::TransferOptions options = sh_shape_transfer_options(a.shape, bands.back());
  if (auto ok = sh::check_transfer_options(options); !ok) return std::unexpected(ok.error());
  return ShLightingErrorSetup{std::move(*light), std::move(*scene), options, std::move(bands)};
}

ShLightingError measure_sh_lighting_error(const ShLightingErrorSetup& setup, const sh::VertexTransfer& transfer,
                                          const sh::TransferProgress& progress) {
  // The exact integral at each of the shape's vertices (not the ground's), once.
  const sh::TransferMesh& mesh = setup.scene.meshes().front();
  const size_t vertices = mesh.positions.size();
  const bool shadowed = setup.options.kind != sh::TransferKind::unshadowed;
  std::vector<glm::dvec3> exact(vertices);
  const auto t0 = std::chrono::steady_clock::now();
  std::atomic<size_t> done{0};
  tbb::parallel_for(size_t(0), vertices, [&](size_t v) {
    exact[v] = setup.light->exact_at(setup.scene, mesh.positions[v], mesh.normals[v], mesh.albedo, shadowed);
    if (progress) progress(++done, vertices);
  });
  ShLightingError result{.vertices = vertices};
  result.exact_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const glm::dvec3& e : exact) result.max_exact = std::max(result.max_exact, max_component(e));

  for (int bands : setup.bands) {
    const std::vector<glm::dvec3> coefficients = setup.light->coefficients(bands);
    ShLightingError::Row row{bands, 0.0, 0.0, 0};
    double squares = 0;
    for (size_t v = 0; v < vertices; ++v) {
      // Σ T_i L_i over the first bands² coefficients (the transfer's prefix: its bands are independent).
      const glm::dvec3 error = sh::shade(transfer, v, coefficients) - exact[v];
      squares += glm::dot(error, error);
      if (const double e = max_component(error); e > row.max_abs) row.max_abs = e, row.at = v;
    }
    row.rms = std::sqrt(squares / (3.0 * double(std::max<size_t>(vertices, 1))));
    result.rows.push_back(row);
  }
  return result;
}

}  // namespace shaderbed
