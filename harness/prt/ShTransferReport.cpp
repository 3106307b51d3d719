#include "prt/ShTransferReport.h"

#include <fmt/format.h>

#include "prt/RgbValues.h"
#include "sh/Basis.h"

namespace shaderbed {
namespace {

// What the report states beside the request and the run.
struct TransferFigures {
  size_t rays = 0, rays_cast = 0;   // cast when computed; now (none from the cache)
  double per_second = 0;
  size_t shape_vertices = 0, ground_vertices = 0, samples = 0;
};

TransferFigures transfer_figures(const ShShapeRequest& shape, const sh::TransferScene& scene,
                                 const sh::TransferOptions& options, const ShTransferRun& run) {
  TransferFigures f;
  f.rays = sh_transfer_rays(scene, options);
  f.rays_cast = run.from_cache ? 0 : f.rays;
  f.per_second = run.from_cache || run.seconds <= 0 ? 0.0 : double(f.rays_cast) / run.seconds;
  f.shape_vertices = scene.meshes().front().positions.size();
  f.ground_vertices = scene.vertex_count() - f.shape_vertices;
  f.samples = size_t(shape.grid) * size_t(shape.grid);
  return f;
}

std::string transfer_json(const ShShapeRequest& a, const sh::TransferScene& scene, const sh::TransferOptions& options,
                          const ShTransferRun& run, const TransferFigures& f, bool coefficients) {
  const auto or_null = [&run](auto value) { return run.from_cache ? nlohmann::json(nullptr) : nlohmann::json(value); };
  nlohmann::json j = sh_shape_json(a);
  j.update({{"bounces", options.bounces},
            {"bands", options.bands},
            {"coefficients_per_vertex", sh::coefficient_count(options.bands)},
            {"vertices", scene.vertex_count()},
            {"shape_vertices", f.shape_vertices},
            {"ground_vertices", f.ground_vertices},
            {"rays", f.rays},
            {"rays_cast", f.rays_cast},
            {"seconds", run.seconds},
            {"rays_per_second", or_null(f.per_second)},
            {"threads", run.threads},
            {"rays_per_second_per_core", or_null(f.per_second / run.threads)},
            {"from_cache", run.from_cache},
            {"cache", run.cache},
            {"cache_file", run.file.empty() ? nlohmann::json(nullptr) : nlohmann::json(run.file.string())},
            {"computed_because", or_null(run.reason)}});
  if (coefficients) {
    // Per mesh (the shape, then the ground), per vertex, bands² RGB coefficients.
    nlohmann::json meshes = nlohmann::json::array();
    for (const sh::VertexTransfer& t : run.transfer) {
      nlohmann::json vertices = nlohmann::json::array();
      for (size_t v = 0; v < t.vertex_count(); ++v) {
        nlohmann::json c = nlohmann::json::array();
        for (const glm::dvec3& x : t.vertex(v)) c.push_back(rgb_json(x));
        vertices.push_back(std::move(c));
      }
      meshes.push_back(std::move(vertices));
    }
    j["transfer"] = std::move(meshes);
  }
  return j.dump(2) + "\n";
}

std::string transfer_text(const ShShapeRequest& a, const sh::TransferScene& scene, const sh::TransferOptions& options,
                          const ShTransferRun& run, const TransferFigures& f, bool coefficients) {
  const std::string kind = options.kind == sh::TransferKind::interreflected
                               ? fmt::format("interreflected ({} bounce{})", options.bounces, options.bounces == 1 ? "" : "s")
                               : a.kind;
  std::string out = fmt::format(
      "{}: {} vertices{}\n", sh_shape_label(a), scene.vertex_count(),
      f.ground_vertices ? fmt::format(" ({} shape + {} ground)", f.shape_vertices, f.ground_vertices) : "");
  out += fmt::format("{} transfer, {} bands ({} coefficients per channel), {} x {} = {} jittered rays per vertex, seed {}\n",
                     kind, options.bands, sh::coefficient_count(options.bands), a.grid, a.grid, f.samples, a.seed);
  if (run.from_cache) {
    out += fmt::format("read from the cache in {:.3f} s: {}\n", run.seconds, run.file.string());
    out += fmt::format("rays: {} when computed (none cast now)\n", f.rays);
  } else {
    out += fmt::format("computed in {:.3f} s ({}): {} rays cast", run.seconds, run.reason, f.rays_cast);
    if (f.rays_cast > 0)
      out += fmt::format(", {:.2f} M rays/s ({:.2f} M per core, {} core{})", f.per_second * 1e-6,
                         f.per_second * 1e-6 / run.threads, run.threads, run.threads == 1 ? "" : "s");
    out += "\n";
    out += fmt::format("cache: {}{}\n", run.cache, run.file.empty() ? "" : ", stored in " + run.file.string());
  }
  if (coefficients)
    for (size_t m = 0; m < run.transfer.size(); ++m)
      for (size_t v = 0; v < run.transfer[m].vertex_count(); ++v) {
        std::string line = fmt::format("{} {}:", m == 0 ? "shape" : "ground", v);
        for (const glm::dvec3& x : run.transfer[m].vertex(v)) line += fmt::format(" ({:.6g} {:.6g} {:.6g})", x.r, x.g, x.b);
        out += line + "\n";
      }
  return out;
}

}  // namespace

nlohmann::json sh_shape_json(const ShShapeRequest& shape) {
  return {{"shape", shape.shape},
          {"tessellation", shape.slices > 0 ? nlohmann::json(nullptr) : nlohmann::json(shape.tessellation)},
          {"slices", shape.slices > 0 ? nlohmann::json(shape.slices) : nlohmann::json(nullptr)},
          {"ground", shape.ground},
          {"kind", shape.kind},
          {"grid", shape.grid},
          {"samples_per_vertex", size_t(shape.grid) * size_t(shape.grid)},
          {"seed", shape.seed}};
}

std::string sh_transfer_report(const ShShapeRequest& shape, const sh::TransferScene& scene, const sh::TransferOptions& options,
                               const ShTransferRun& run, bool coefficients, bool json) {
  const TransferFigures figures = transfer_figures(shape, scene, options, run);
  return json ? transfer_json(shape, scene, options, run, figures, coefficients)
              : transfer_text(shape, scene, options, run, figures, coefficients);
}

}  // namespace shaderbed
