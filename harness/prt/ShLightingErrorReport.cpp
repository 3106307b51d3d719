#include "prt/ShLightingErrorReport.h"

#include <fmt/format.h>

#include "prt/ShTransferReport.h"
#include "sh/Basis.h"

namespace shaderbed {
namespace {

std::string exact_integral_method(const ShLightingErrorRequest& a) {
  return a.light == "directional"
             ? "the delta light in closed form (sh::exact_directional)"
             : fmt::format("Gauss-Legendre {} x {} quadrature of the light itself (sh::exact_diffuse_radiance)",
                           kExactQuadratureTheta, kExactQuadraturePhi);
}

std::string light_label(const ShLightingErrorRequest& a) {
  const std::vector<double>& d = a.direction;
  if (a.light == "directional") return fmt::format("directional (D3DX normalisation) toward ({:g}, {:g}, {:g})", d[0], d[1], d[2]);
  if (a.light == "cone")
    return fmt::format("cone toward ({:g}, {:g}, {:g}), half-angle {:g} rad", d[0], d[1], d[2], a.radius);
  if (a.light == "sky") return "the analytic sky";
  return fmt::format("the environment map {} ({})", a.probe, a.mapping);
}

std::string lighting_error_json(const ShLightingErrorRequest& a, const ShLightingErrorSetup& setup, const ShTransferRun& run,
                                const ShLightingError& e) {
  nlohmann::json j = sh_shape_json(a.shape);
  j.update({{"vertices", e.vertices},
            {"light", a.light},
            {"light_description", light_label(a)},
            {"transfer_bands", setup.options.bands},
            {"transfer_from_cache", run.from_cache},
            {"transfer_seconds", run.seconds},
            {"cache_file", run.file.empty() ? nlohmann::json(nullptr) : nlohmann::json(run.file.string())},
            {"exact_method", exact_integral_method(a)},
            {"exact_seconds", e.exact_seconds},
            {"max_exact", e.max_exact}});
  nlohmann::json rows = nlohmann::json::array();
  for (const ShLightingError::Row& r : e.rows)
    rows.push_back({{"bands", r.bands}, {"coefficients", sh::coefficient_count(r.bands)}, {"max_abs", r.max_abs},
                    {"rms", r.rms}, {"max_abs_vertex", r.at}});
  j["rows"] = std::move(rows);
  return j.dump(2) + "\n";
}

std::string lighting_error_text(const ShLightingErrorRequest& a, const ShLightingErrorSetup& setup, const ShTransferRun& run,
                                const ShLightingError& e) {
  const ShShapeRequest& s = a.shape;
  std::string out = fmt::format("{}: {} vertices compared, {} transfer, {} x {} = {} jittered rays per vertex, seed {}\n",
                                sh_shape_label(s), e.vertices, s.kind, s.grid, s.grid, size_t(s.grid) * size_t(s.grid),
                                s.seed);
  out += fmt::format("transfer: {} bands, {} in {:.3f} s\n", setup.options.bands,
                     run.from_cache ? "read from the cache" : "computed (" + run.reason + ")", run.seconds);
  out += fmt::format("light: {}\n", light_label(a));
  out += fmt::format("exact: {}, same visibility, {:.3f} s; largest exact radiance {:.6g}\n", exact_integral_method(a),
                     e.exact_seconds, e.max_exact);
  out += fmt::format("\n{:>5} {:>12} {:>16} {:>16}\n", "bands", "coefficients", "max |SH-exact|", "RMS");
  for (const ShLightingError::Row& r : e.rows)
    out += fmt::format("{:>5} {:>12} {:>16.4e} {:>16.4e}\n", r.bands, sh::coefficient_count(r.bands), r.max_abs, r.rms);
  return out;
}

}  // namespace

std::string sh_lighting_error_report(const ShLightingErrorRequest& request, const ShLightingErrorSetup& setup,
                                     const ShTransferRun& run, const ShLightingError& error, bool json) {
  return json ? lighting_error_json(request, setup, run, error) : lighting_error_text(request, setup, run, error);
}

}  // namespace shaderbed
