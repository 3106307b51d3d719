// `shaderbed sh project|transfer|eval`: the spherical-harmonic precompute steps (docs/sh.md)
// from the command line: options and wiring; the work and the reports are prt/'s
// (ShProjection, ShShape, ShTransferRun, ShLightingError). Bad input (bands outside 1..12,
// grid < 1, an unknown shape, kind or light, an unreadable probe) is one line on stderr, exit 2.
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "cli/commands/Command.h"
#include "core/CacheSettings.h"
#include "prt/ShLightingErrorReport.h"
#include "prt/ShProjectionReport.h"
#include "prt/ShTransferReport.h"
#include "prt/StepProgress.h"
#include "scene/Primitives.h"

namespace shaderbed {
namespace sh_command {   // named: the command files are compiled as one unity unit

constexpr int kMaxBands = 12, kMaxGrid = 1000;   // kMaxGrid: sh::compute_transfer's limit, a million samples

// What each subcommand asks of prt/, and how to print it.
struct ProjectArguments { ShProjectionRequest request; bool json = false; };
struct TransferArguments { ShShapeRequest shape; int bands = 4; bool coefficients = false, json = false; };
struct EvalArguments { ShLightingErrorRequest request; bool json = false; };

int bad_input(const std::string& command, const std::string& message) {
  fmt::print(stderr, "shaderbed: sh {}: {}\n", command, message);
  return kExitBadInput;
}

void add_shape_options(CLI::App* cmd, ShShapeRequest& a, bool& json, bool eval) {
  cmd->add_option("--shape", a.shape, "The shape: sphere, cube, cone or torus (the run engine's)")->required()
      ->check(CLI::IsMember(shape_names()));
  CLI::Option* tessellation = cmd->add_option("--tessellation", a.tessellation, "low or high, as a case's `tessellation`")
                                  ->capture_default_str()->check(CLI::IsMember({"low", "high"}));
  cmd->add_option("--slices", a.slices,
                  "Any density instead: sphere and cone N slices and N/2 stacks, torus N/2 sides and N rings, cube "
                  "N/8 subdivisions per edge")
      ->check(CLI::Range(4, 4096))->excludes(tessellation);
  cmd->add_flag("--ground", a.ground,
                "Stand the shape on a ground plane (albedo 0.8), as a case's `ground = true`: it shadows the shape and, "
                "inter-reflected, lights it");
  cmd->add_option("--albedo", a.albedo, "The shape's diffuse albedo r,g,b (in the transfer)")->delimiter(',')->expected(3)
      ->check(CLI::Range(0.0, 1.0))->capture_default_str();
  cmd->add_option("--kind", a.kind,
                  eval ? "unshadowed or shadowed transfer (inter-reflected light has no exact reference here)"
                       : "unshadowed, shadowed or interreflected transfer")
      ->capture_default_str()->check(CLI::IsMember({"unshadowed", "shadowed", "interreflected"}));
  if (!eval)
    cmd->add_option("--bounces", a.bounces, "Bounces of the inter-reflected transfer")->capture_default_str()
        ->check(CLI::Range(0, 16));
  cmd->add_option("--grid", a.grid, "The book's jittered grid: grid x grid rays per vertex")->capture_default_str()
      ->check(CLI::Range(1, kMaxGrid));
  cmd->add_option("--seed", a.seed, "Seed of the jittered samples")->capture_default_str();
  cmd->add_flag("--no-cache", a.no_cache,
                "Compute the transfer even if the cache holds it, and do not store it (the cache is "
                "<cache root>/sh, as `shaderbed run` uses; --cache-dir chooses the root)");
  cmd->add_flag("--json", json, "Print JSON instead of text");
}

// The transfer, its progress on stderr as "sh <command>: <step>"; a failure is said here.
std::optional<ShTransferRun> transfer_with_progress(const sh::TransferScene& scene, const sh::TransferOptions& options,
                                                    bool no_cache, const std::string& command, const std::string& step) {
  StepProgress progress("sh " + command + ": " + step);
  auto run = run_sh_transfer(scene, options, no_cache, cache_settings().root, progress.callback());
  progress.finish();
  if (!run) {
    fmt::print(stderr, "shaderbed: sh {}: {}\n", command, run.error());
    return std::nullopt;
  }
  if (!run->write_error.empty())
    fmt::print(stderr, "shaderbed: sh: could not store the transfer in the cache: {}\n", run->write_error);
  return std::move(*run);
}

int run_transfer(const TransferArguments& a) {
  auto scene = make_sh_shape_scene(a.shape);
  if (!scene) return bad_input("transfer", scene.error());
  const sh::TransferOptions options = sh_shape_transfer_options(a.shape, a.bands);
  if (auto ok = sh::check_transfer_options(options); !ok) return bad_input("transfer", ok.error());
  auto run = transfer_with_progress(*scene, options, a.shape.no_cache, "transfer", "vertices");
  if (!run) return kExitFail;
  fmt::print("{}", sh_transfer_report(a.shape, *scene, options, *run, a.coefficients, a.json));
  return 0;
}

int run_eval(const EvalArguments& a) {
  auto setup = prepare_sh_lighting_error(a.request);
  if (!setup) return bad_input("eval", setup.error());
  auto run = transfer_with_progress(setup->scene, setup->options, a.request.shape.no_cache, "eval", "transfer");
  if (!run) return kExitFail;
  StepProgress progress("sh eval: exact integral, vertices");
  const ShLightingError error = measure_sh_lighting_error(*setup, run->transfer.front(), progress.callback());
  progress.finish();
  fmt::print("{}", sh_lighting_error_report(a.request, *setup, *run, error, a.json));
  return 0;
}

}  // namespace sh_command

Command add_sh_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "sh", "Spherical-harmonic precompute steps (book Ch. 8 and 9, docs/sh.md): project a light, compute a shape's "
      "per-vertex transfer, measure the SH approximation's error against the exact lighting integral");
  cmd->require_subcommand(1);

  auto p = std::make_shared<sh_command::ProjectArguments>();
  ShProjectionRequest& pr = p->request;
  CLI::App* project = cmd->add_subcommand(
      "project", "Print a light's SH coefficients (index i = l(l+1)+m, l, m, value; RGB for lights, a scalar for the "
      "book's test function) by the book's jittered projection (grid x grid samples, 4 pi / N each) beside the exact "
      "ones (the lights' closed forms, or Gauss-Legendre for a map), and the largest differences. --light book --bands "
      "5 --grid 100 is the book's Fig. 8.14 example, printed with the values the book gives.");
  project->fallthrough();
  CLI::Option* light_option =
      project->add_option("--light", pr.light,
                          "book (the test function of Figs. 8.13/8.14), directional, cone (D3DX semantics), sky (the "
                          "analytic sky) or probe (an environment map)")
          ->capture_default_str()->check(CLI::IsMember({"book", "directional", "cone", "sky", "probe"}));
  CLI::Option* probe_option = project->add_option(
      "--probe", pr.probe, "The environment map of --light probe: .hdr, .exr or anything OpenImageIO reads");
  project->add_option("--mapping", pr.mapping, "The probe's layout: latlong or angular (Debevec's light probe)")
      ->capture_default_str()->check(CLI::IsMember({"latlong", "angular"}));
  project->add_option("--bands", pr.bands, "Bands (bands² coefficients), 1 to 12")->capture_default_str()
      ->check(CLI::Range(1, sh_command::kMaxBands));
  project->add_option("--grid", pr.grid, "The jittered grid: grid x grid samples")->capture_default_str()
      ->check(CLI::Range(1, sh_command::kMaxGrid));
  project->add_option("--seed", pr.seed, "Seed of the jittered samples")->capture_default_str();
  project->add_option("--direction", pr.direction,
                      "Toward the directional or cone light, x,y,z in the scene (y up; the default is the scene's light)")
      ->delimiter(',')->expected(3)->capture_default_str();
  project->add_option("--radius", pr.radius, "The cone's half-angle in radians, 0 to pi")->capture_default_str()
      ->check(CLI::Range(0.0, M_PI));
  project->add_flag("--exact", pr.exact_only, "Only the exact coefficients (no jittered projection)");
  project->add_flag("--json", p->json, "Print JSON instead of text");

  auto t = std::make_shared<sh_command::TransferArguments>();
  CLI::App* transfer = cmd->add_subcommand(
      "transfer", "Compute a shape's per-vertex SH transfer (diffuse unshadowed, shadowed by Embree ray casts, or "
      "inter-reflected), or read it from the cache `shaderbed run` uses (<cache root>/sh); print the vertices, the "
      "rays cast, the time, rays per second, and whether it came from the cache. Progress goes to stderr.");
  transfer->fallthrough();
  sh_command::add_shape_options(transfer, t->shape, t->json, false);
  transfer->add_option("--bands", t->bands, "Bands of the transfer (bands² coefficients per channel), 1 to 12")
      ->capture_default_str()->check(CLI::Range(1, sh_command::kMaxBands));
  transfer->add_flag("--coefficients", t->coefficients,
                     "Also print every vertex's coefficients (with --json: \"transfer\", per mesh, per vertex, "
                     "bands² [r, g, b])");

  auto e = std::make_shared<sh_command::EvalArguments>();
  ShLightingErrorRequest& er = e->request;
  CLI::App* eval = cmd->add_subcommand(
      "eval", "For each band count, the error of per-vertex SH lighting over the shape's vertices: Σ T_i L_i in double "
      "(the jittered transfer, the light's coefficients) against the exact lighting integral with the same visibility "
      "(the delta in closed form for the directional light, Gauss-Legendre quadrature for the others); max abs and RMS "
      "over vertices and channels.");
  eval->fallthrough();
  sh_command::add_shape_options(eval, er.shape, e->json, true);
  eval->add_option("--light", er.light, "directional, cone, sky or probe")->capture_default_str()
      ->check(CLI::IsMember({"directional", "cone", "sky", "probe"}));
  eval->add_option("--probe", er.probe, "The environment map of --light probe");
  eval->add_option("--mapping", er.mapping, "The probe's layout: latlong or angular")->capture_default_str()
      ->check(CLI::IsMember({"latlong", "angular"}));
  eval->add_option("--direction", er.direction, "Toward the directional or cone light, x,y,z in the scene (y up)")
      ->delimiter(',')->expected(3)->capture_default_str();
  eval->add_option("--radius", er.radius, "The cone's half-angle in radians")->capture_default_str()
      ->check(CLI::Range(0.0, M_PI));
  CLI::Option* list = eval->add_option("--bands-list", er.bands_list, "Band counts to compare, e.g. 1,2,4 (default 1,...,8)")
                          ->delimiter(',')->check(CLI::Range(1, sh_command::kMaxBands));
  eval->add_option("--bands", er.bands, "One band count instead, 1 to 12")->check(CLI::Range(1, sh_command::kMaxBands))
      ->excludes(list);

  return {cmd, [p, t, e, project, transfer, eval, light_option, probe_option] {
            try {
              if (project->parsed()) {
                ShProjectionRequest a = p->request;   // --probe alone means --light probe
                if (probe_option->count() > 0 && light_option->count() == 0) a.light = "probe";
                if (!a.probe.empty() && a.light != "probe")
                  return sh_command::bad_input("project", "--probe is the map of --light probe, not of --light " + a.light);
                auto projection = project_sh_light(a);
                if (!projection) return sh_command::bad_input("project", projection.error());
                fmt::print("{}", sh_projection_report(*projection, p->json));
                return 0;
              }
              if (transfer->parsed()) return sh_command::run_transfer(*t);
              if (eval->parsed()) return sh_command::run_eval(*e);
            } catch (const std::exception& error) {
              fmt::print(stderr, "shaderbed: sh: {}\n", error.what());
              return kExitFail;
            }
            fmt::print(stderr, "shaderbed: sh: a subcommand is required: project, transfer or eval\n");
            return kExitBadInput;
          }};
}

}  // namespace shaderbed
