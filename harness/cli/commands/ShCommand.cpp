// `shaderbed sh project|transfer|eval`: the spherical-harmonic precompute steps (issue 12,
// docs/sh.md) from the command line.
//   project   a light's coefficients by the book's jittered projection beside the exact ones
//             (closed forms, or Gauss-Legendre for a map); the book's test function with the
//             values its Fig. 8.14 table prints.
//   transfer  a shape's per-vertex transfer, from the cache the run engine uses
//             (<cache root>/sh) or computed: vertices, rays, time, rays per second.
//   eval      for each band count, the error of per-vertex SH lighting (Σ T_i L_i in double)
//             against the exact integral at the shape's vertices, with the same visibility.
// Bad input (bands outside 1..12, grid < 1, an unknown shape, kind or light, a probe that
// cannot be read) is one line on stderr and exit 2.
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <expected>
#include <cmath>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <type_traits>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands/Command.h"
#include "core/CacheSettings.h"
#include "prt/ProbeFile.h"
#include "prt/ShCase.h"
#include "prt/ShLight.h"
#include "scene/Primitives.h"
#include "sh/Basis.h"
#include "sh/EnvironmentMap.h"
#include "sh/Lights.h"
#include "sh/Projection.h"
#include "sh/Sampling.h"
#include "sh/Transfer.h"
#include "sh/TransferCache.h"

namespace shaderbed {
// A named namespace: the command files are compiled as one unity unit.
namespace sh_command {

constexpr int kMaxBands = 12;
constexpr int kMaxGrid = 1000;   // sh::compute_transfer's limit: a million samples

// The book's Fig. 8.14 worked example as printed (5 bands, 100 x 100 jittered samples),
// i = 0..24; digest §2.3. Its zeros by symmetry (i = 5, 7, 10, ...) are Monte Carlo noise.
constexpr double kBookPrinted[25] = {
    0.399249,  -0.210748, 0.286867,  0.282772,  -0.315302,  //
    -0.000398, 0.131591,  0.000977,  0.093585,  -0.249934,  //
    -0.000721, 0.122896,  0.304576,  -0.164276, -0.000615,  //
    -0.091265, -0.101271, -0.000139, 0.132715,  -0.000166,  //
    0.344469,  0.001542,  -0.041332, -0.000069, -0.153648};

// The quadrature the run engine integrates non-delta lights with (prt/ShLight.cpp).
constexpr int kQuadratureTheta = 96, kQuadraturePhi = 192;

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The cores this process may run on (what TBB spreads the transfer over).
unsigned worker_threads() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) return unsigned(std::max(1, CPU_COUNT(&set)));
  return std::max(1u, std::thread::hardware_concurrency());
}

// f(i) for i in [0, n) on every core.
template <class F>
void parallel_for(size_t n, const F& f) {
  const size_t threads = std::clamp<size_t>(worker_threads(), 1, std::max<size_t>(n, 1));
  std::atomic<size_t> next{0};
  auto work = [&] {
    for (size_t i; (i = next.fetch_add(1)) < n;) f(i);
  };
  std::vector<std::jthread> pool;
  for (size_t t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
}

// Progress of a long step on stderr. On a terminal: one line refreshed in place (at most
// ten times a second) and erased at the end. Otherwise: nothing for the first two seconds,
// then a line at each quarter, so at most three lines in a log. Thread-safe.
class Progress {
 public:
  explicit Progress(std::string what) : what_(std::move(what)), terminal_(isatty(STDERR_FILENO) != 0) {}
  ~Progress() { finish(); }

  void update(size_t done, size_t total) {
    std::lock_guard lock(mutex_);
    if (total == 0) return;
    const auto now = Clock::now();
    const double seconds = std::chrono::duration<double>(now - start_).count();
    if (terminal_) {
      if (done < total && drawn_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
      last_draw_ = now;
      drawn_ = true;
      fmt::print(stderr, "\r{}: {}/{} ({:.0f}%), {:.1f} s\033[K", what_, done, total, 100.0 * double(done) / double(total),
                 seconds);
      return;
    }
    const size_t quarter = done * 4 / total;
    if (seconds >= 2.0 && quarter >= next_quarter_ && quarter < 4) {
      fmt::print(stderr, "{}: {}/{} ({}%), {:.1f} s\n", what_, done, total, quarter * 25, seconds);
      next_quarter_ = quarter + 1;
    }
  }
  void finish() {
    std::lock_guard lock(mutex_);
    if (drawn_) fmt::print(stderr, "\r\033[K");
    drawn_ = false;
  }
  sh::TransferProgress callback() {
    return [this](size_t done, size_t total) { update(done, total); };
  }

 private:
  std::string what_;
  bool terminal_;
  Clock::time_point start_ = Clock::now(), last_draw_ = start_;
  bool drawn_ = false;
  size_t next_quarter_ = 1;
  std::mutex mutex_;
};

int bad_input(const std::string& command, const std::string& message) {
  fmt::print(stderr, "shaderbed: sh {}: {}\n", command, message);
  return kExitBadInput;
}

// A message about a file that names it.
std::string naming(const std::string& path, const std::string& message) {
  return message.find(path) == std::string::npos ? path + ": " + message : message;
}

nlohmann::json rgb_json(const glm::dvec3& v) { return {v.r, v.g, v.b}; }

double max_component(const glm::dvec3& v) { return std::max({std::abs(v.r), std::abs(v.g), std::abs(v.b)}); }

// ---- project ------------------------------------------------------------------------------

struct ProjectArguments {
  std::string light = "book";
  std::string probe, mapping = "latlong";
  int bands = 5, grid = 100;
  uint64_t seed = sh::default_seed;
  std::vector<double> direction{0, 1, 0};
  double radius = 0.6;
  bool exact_only = false, json = false;
};

// Projection onto a grid x grid jittered set (Sampling.h) in slices of samples, so the basis
// table stays small at a million samples; one slice (grid <= 128) is exactly sh::project.
template <class T, class F>
std::vector<T> jittered_projection(const F& f, int bands, int grid, uint64_t seed) {
  constexpr size_t kSlice = 16384;
  const std::vector<sh::Sample> samples = sh::jittered_samples(grid, seed);
  std::vector<T> sum(size_t(sh::coefficient_count(bands)), T(0.0));
  for (size_t first = 0; first < samples.size(); first += kSlice) {
    const sh::SampleSet slice(std::vector<sh::Sample>(samples.begin() + std::ptrdiff_t(first),
                                                      samples.begin() + std::ptrdiff_t(std::min(samples.size(), first + kSlice))),
                              bands);
    std::vector<T> part;
    if constexpr (std::is_same_v<T, double>) part = sh::project(f, slice);
    else part = sh::project_rgb(f, slice);
    for (size_t i = 0; i < sum.size(); ++i) sum[i] += part[i];
  }
  return sum;
}

int run_project(const ProjectArguments& a) {
  const bool book = a.light == "book";
  const bool sampled = !a.exact_only;
  const glm::dvec3 white(1.0);
  const glm::dvec3 scene_direction(a.direction[0], a.direction[1], a.direction[2]);
  std::string description, exact_method;
  std::vector<double> jittered_scalar, exact_scalar;
  std::vector<glm::dvec3> jittered_rgb, exact_rgb;
  bool delta = false;   // no sampled projection exists

  if (book) {
    description = "the book's test function (Eq. 13 with the code's 5 cos(theta), Figs. 8.13 and 8.14)";
    exact_method = "exact: its two zonal lobes integrated in closed form";
    if (sampled) jittered_scalar = jittered_projection<double>([](const glm::dvec3& d) { return sh::book_test_function(d); },
                                                               a.bands, a.grid, a.seed);
    exact_scalar = sh::book_test_coefficients_exact(a.bands);
  } else if (a.light == "directional" ||
             (a.light == "cone" && a.radius < sh::ConeLight::directional_below)) {
    auto light = sh::make_directional_light(sh::to_sh_frame(scene_direction), white);
    if (!light) return bad_input("project", light.error());
    description = fmt::format("a directional light (D3DXSHEvalDirectionalLight) toward ({:g}, {:g}, {:g}) in the scene, "
                              "colour 1{}",
                              a.direction[0], a.direction[1], a.direction[2],
                              a.light == "cone" ? fmt::format(" (a cone of radius {:g} < {:g} is one)", a.radius,
                                                              sh::ConeLight::directional_below)
                                                : "");
    exact_method = fmt::format("exact: pi / N({}) y(d) with D3DX's N({}) = {:g}; a delta has no sampled projection",
                               a.bands, a.bands, sh::directional_light_normalisation(a.bands));
    exact_rgb = light->coefficients(a.bands);
    delta = true;
  } else if (a.light == "cone") {
    auto light = sh::make_cone_light(sh::to_sh_frame(scene_direction), a.radius, white);
    if (!light) return bad_input("project", light.error());
    const sh::ConeLight cone = *light;
    description = fmt::format("a cone light (D3DXSHEvalConeLight) toward ({:g}, {:g}, {:g}) in the scene, half-angle "
                              "{:g} rad, radiance {:.6g} inside",
                              a.direction[0], a.direction[1], a.direction[2], a.radius, cone.radiance().r);
    exact_method = "exact: the cap's zonal integral in closed form";
    if (sampled) jittered_rgb = jittered_projection<glm::dvec3>([&](const glm::dvec3& d) { return cone(d); }, a.bands,
                                                                a.grid, a.seed);
    exact_rgb = cone.coefficients(a.bands);
  } else if (a.light == "sky") {
    const sh::SkyLight sky;
    description = "the analytic sky (docs/sh.md: zenith, horizon and ground colours, a sun 40 degrees up)";
    exact_method = "exact: zonal polynomials integrated in closed form";
    if (sampled)
      jittered_rgb = jittered_projection<glm::dvec3>([&](const glm::dvec3& d) { return sky(d); }, a.bands, a.grid, a.seed);
    exact_rgb = sky.coefficients(a.bands);
  } else {   // probe
    if (a.probe.empty()) return bad_input("project", "--light probe needs --probe FILE (an .hdr or .exr environment map)");
    auto map = read_probe(a.probe, a.mapping == "angular" ? sh::MapLayout::angular : sh::MapLayout::latlong);
    if (!map) return bad_input("project", naming(a.probe, map.error().message));
    description = fmt::format("the environment map {} ({} x {}, {})", a.probe, map->width(), map->height(), a.mapping);
    exact_method = fmt::format("exact: Gauss-Legendre {} x {} (the run engine's rule; a bilinear map is not band-limited)",
                               kQuadratureTheta, kQuadraturePhi);
    const auto lookup = [&](const glm::dvec3& d) { return map->lookup(d); };
    if (sampled) jittered_rgb = jittered_projection<glm::dvec3>(lookup, a.bands, a.grid, a.seed);
    exact_rgb = sh::project_rgb(lookup, sh::SampleSet(sh::gauss_legendre_samples(kQuadratureTheta, kQuadraturePhi), a.bands));
  }
  const bool has_jittered = sampled && !delta;
  const size_t n = size_t(sh::coefficient_count(a.bands));
  const size_t book_count = book ? std::min<size_t>(n, 25) : 0;

  // The largest differences and where they are.
  double max_jittered = 0, max_book = 0, max_book_jittered = 0;
  size_t at_jittered = 0, at_book = 0, at_book_jittered = 0;
  for (size_t i = 0; i < n; ++i) {
    if (has_jittered) {
      const double d = book ? std::abs(jittered_scalar[i] - exact_scalar[i]) : max_component(jittered_rgb[i] - exact_rgb[i]);
      if (d > max_jittered) max_jittered = d, at_jittered = i;
    }
    if (i < book_count) {
      if (const double d = std::abs(kBookPrinted[i] - exact_scalar[i]); d > max_book) max_book = d, at_book = i;
      if (has_jittered)
        if (const double d = std::abs(kBookPrinted[i] - jittered_scalar[i]); d > max_book_jittered)
          max_book_jittered = d, at_book_jittered = i;
    }
  }
  auto lm = [](size_t i) {
    const int l = int(std::sqrt(double(i)));
    return std::pair<int, int>(l, int(i) - l * (l + 1));
  };

  if (a.json) {
    nlohmann::json j{{"light", a.light}, {"description", description}, {"bands", a.bands},
                     {"coefficient_count", n}, {"exact_method", exact_method}};
    if (has_jittered) {
      j["grid"] = a.grid;
      j["samples"] = size_t(a.grid) * size_t(a.grid);
      j["seed"] = a.seed;
    }
    if (a.light == "probe") j["probe"] = a.probe, j["mapping"] = a.mapping;
    nlohmann::json rows = nlohmann::json::array();
    for (size_t i = 0; i < n; ++i) {
      const auto [l, m] = lm(i);
      nlohmann::json row{{"i", i}, {"l", l}, {"m", m}};
      if (has_jittered) row["jittered"] = book ? nlohmann::json(jittered_scalar[i]) : rgb_json(jittered_rgb[i]);
      row["exact"] = book ? nlohmann::json(exact_scalar[i]) : rgb_json(exact_rgb[i]);
      if (i < book_count) row["book"] = kBookPrinted[i];
      rows.push_back(std::move(row));
    }
    j["coefficients"] = std::move(rows);
    if (has_jittered) j["max_jittered_vs_exact"] = {{"value", max_jittered}, {"i", at_jittered}};
    if (book_count > 0) {
      j["max_book_vs_exact"] = {{"value", max_book}, {"i", at_book}};
      if (has_jittered) j["max_book_vs_jittered"] = {{"value", max_book_jittered}, {"i", at_book_jittered}};
    }
    fmt::print("{}\n", j.dump(2));
    return 0;
  }

  fmt::print("{}, {} bands ({} coefficients, SH frame z up)\n", description, a.bands, n);
  if (has_jittered)
    fmt::print("jittered: the book's {} x {} stratified grid = {} samples, seed {}\n", a.grid, a.grid,
               size_t(a.grid) * size_t(a.grid), a.seed);
  fmt::print("{}\n", exact_method);
  if (book) {
    fmt::print("\n{:>4} {:>3} {:>3}  {:>12} {:>12} {:>12}\n", "i", "l", "m", has_jittered ? "jittered" : "", "exact",
               book_count ? "book" : "");
    for (size_t i = 0; i < n; ++i) {
      const auto [l, m] = lm(i);
      fmt::print("{:>4} {:>3} {:>3}  {:>12} {:>12.6f} {:>12}\n", i, l, m,
                 has_jittered ? fmt::format("{:.6f}", jittered_scalar[i]) : "", exact_scalar[i],
                 i < book_count ? fmt::format("{:.6f}", kBookPrinted[i]) : "");
    }
  } else {
    auto triple = [](const glm::dvec3& v) { return fmt::format("{:>11.6f} {:>11.6f} {:>11.6f}", v.r, v.g, v.b); };
    fmt::print("\n{:>4} {:>3} {:>3}  {}{:>35}\n", "i", "l", "m",
               has_jittered ? fmt::format("{:>35}  ", "jittered (r g b)") : "", "exact (r g b)");
    for (size_t i = 0; i < n; ++i) {
      const auto [l, m] = lm(i);
      fmt::print("{:>4} {:>3} {:>3}  {}{}\n", i, l, m, has_jittered ? triple(jittered_rgb[i]) + "  " : "",
                 triple(exact_rgb[i]));
    }
  }
  fmt::print("\n");
  if (has_jittered) fmt::print("max |jittered - exact| = {:.3e} (i = {})\n", max_jittered, at_jittered);
  if (book_count > 0) {
    fmt::print("max |book - exact|     = {:.3e} (i = {})\n", max_book, at_book);
    if (has_jittered) fmt::print("max |book - jittered|  = {:.3e} (i = {})\n", max_book_jittered, at_book_jittered);
  }
  return 0;
}

// ---- the shape and its transfer -----------------------------------------------------------

struct ShapeArguments {
  std::string shape;
  std::string tessellation = "low";
  int slices = 0;   // 0: --tessellation
  bool ground = false;
  std::vector<double> albedo{1, 1, 1};
  std::string kind = "shadowed";
  int bounces = 1;
  int grid = 100;
  uint64_t seed = sh::default_seed;
  bool no_cache = false, json = false;
};

void add_shape_options(CLI::App* cmd, ShapeArguments& a, bool eval) {
  cmd->add_option("--shape", a.shape, "The shape: sphere, cube, cone or torus (the run engine's)")
      ->required()
      ->check(CLI::IsMember(shape_names()));
  CLI::Option* tessellation = cmd->add_option("--tessellation", a.tessellation, "low or high, as a case's `tessellation`")
                                  ->capture_default_str()
                                  ->check(CLI::IsMember({"low", "high"}));
  cmd->add_option("--slices", a.slices,
                  "Any density instead: sphere and cone N slices and N/2 stacks, torus N/2 sides and N rings, cube "
                  "N/8 subdivisions per edge")
      ->check(CLI::Range(4, 4096))
      ->excludes(tessellation);
  cmd->add_flag("--ground", a.ground,
                "Stand the shape on a ground plane (albedo 0.8), as a case's `ground = true`: it shadows the shape and, "
                "inter-reflected, lights it");
  cmd->add_option("--albedo", a.albedo, "The shape's diffuse albedo r,g,b (in the transfer)")
      ->delimiter(',')
      ->expected(3)
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--kind", a.kind,
                  eval ? "unshadowed or shadowed transfer (inter-reflected light has no exact reference here)"
                       : "unshadowed, shadowed or interreflected transfer")
      ->capture_default_str()
      ->check(CLI::IsMember({"unshadowed", "shadowed", "interreflected"}));
  if (!eval)
    cmd->add_option("--bounces", a.bounces, "Bounces of the inter-reflected transfer")
        ->capture_default_str()
        ->check(CLI::Range(0, 16));
  cmd->add_option("--grid", a.grid, "The book's jittered grid: grid x grid rays per vertex")
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxGrid));
  cmd->add_option("--seed", a.seed, "Seed of the jittered samples")->capture_default_str();
  cmd->add_flag("--no-cache", a.no_cache,
                "Compute the transfer even if the cache holds it, and do not store it (the cache is "
                "<cache root>/sh, as `shaderbed run` uses; --cache-dir chooses the root)");
  cmd->add_flag("--json", a.json, "Print JSON instead of text");
}

sh::TransferKind transfer_kind(const std::string& kind) {
  return kind == "unshadowed" ? sh::TransferKind::unshadowed
         : kind == "interreflected" ? sh::TransferKind::interreflected
                                    : sh::TransferKind::shadowed;
}

std::string shape_label(const ShapeArguments& a) {
  return fmt::format("{} ({}){}", a.shape, a.slices > 0 ? fmt::format("{} slices", a.slices) : a.tessellation,
                     a.ground ? " on a ground plane" : "");
}

struct ShapeScene {
  Mesh mesh;
  sh::TransferScene scene;
};

std::expected<ShapeScene, std::string> make_shape_scene(const ShapeArguments& a) {
  std::optional<Mesh> mesh = a.slices > 0 ? make_shape(a.shape, a.slices)
                                          : make_shape(a.shape, a.tessellation == "high" ? Tessellation::high : Tessellation::low);
  if (!mesh) return std::unexpected(fmt::format("--shape {}: no such shape (sphere, cube, cone, torus)", a.shape));
  auto scene = sh_transfer_scene(*mesh, glm::dvec3(a.albedo[0], a.albedo[1], a.albedo[2]), a.ground);
  if (!scene) return std::unexpected(scene.error());
  return ShapeScene{std::move(*mesh), std::move(*scene)};
}

sh::TransferOptions transfer_options(const ShapeArguments& a, int bands) {
  sh::TransferOptions o;
  o.kind = transfer_kind(a.kind);
  o.bands = bands;
  o.grid = a.grid;
  o.seed = a.seed;
  o.bounces = o.kind == sh::TransferKind::interreflected ? a.bounces : 0;
  return o;
}

// The rays compute_transfer casts: one per sample above each vertex's horizon, in the direct
// pass (shadowed) and in each bounce (closest hits); none unshadowed.
size_t transfer_rays(const sh::TransferScene& scene, const sh::TransferOptions& o) {
  if (o.kind == sh::TransferKind::unshadowed) return 0;
  std::vector<glm::dvec3> directions;
  for (const sh::Sample& s : sh::jittered_samples(o.grid, o.seed))
    directions.push_back(sh::from_sh_frame(s.direction / glm::length(s.direction)));
  size_t above = 0;
  for (const sh::TransferMesh& mesh : scene.meshes())
    for (const glm::dvec3& normal : mesh.normals)
      for (const glm::dvec3& d : directions) above += glm::dot(normal, d) > 0.0 ? 1 : 0;
  return above * size_t(1 + (o.kind == sh::TransferKind::interreflected ? o.bounces : 0));
}

struct TransferRun {
  std::vector<sh::VertexTransfer> transfer;
  bool from_cache = false;
  std::string cache;         // "on", or why it is off
  std::filesystem::path file;
  std::string reason;        // why it was computed
  double seconds = 0;
};

std::expected<TransferRun, std::string> run_transfer(const sh::TransferScene& scene, const sh::TransferOptions& o,
                                                     bool no_cache, const std::string& what) {
  TransferRun run;
  const std::string root = cache_settings().root;
  Progress progress(what);
  const auto t0 = Clock::now();
  if (no_cache || root.empty()) {
    run.cache = no_cache ? "off (--no-cache)" : "off (no cache folder: set --cache-dir or $SHADERBED_CACHE_DIR)";
    auto computed = sh::compute_transfer(scene, o, progress.callback());
    if (!computed) return std::unexpected(computed.error());
    run.transfer = std::move(*computed);
    run.reason = no_cache ? "--no-cache" : "no cache folder";
  } else {
    run.cache = "on";
    auto cached = sh::cached_transfer_report(scene, o, std::filesystem::path(root) / "sh", progress.callback());
    if (!cached) return std::unexpected(cached.error());
    if (!cached->write_error.empty())
      fmt::print(stderr, "shaderbed: sh: could not store the transfer in the cache: {}\n", cached->write_error);
    run.transfer = std::move(cached->transfer);
    run.from_cache = !cached->computed;
    run.file = cached->file;
    run.reason = cached->reason;
  }
  run.seconds = seconds_since(t0);
  progress.finish();
  return run;
}

// ---- transfer -----------------------------------------------------------------------------

struct TransferArguments {
  ShapeArguments shape;
  int bands = 4;
  bool coefficients = false;
};

int run_transfer_command(const TransferArguments& a) {
  auto made = make_shape_scene(a.shape);
  if (!made) return bad_input("transfer", made.error());
  const sh::TransferScene& scene = made->scene;
  const sh::TransferOptions options = transfer_options(a.shape, a.bands);
  if (auto ok = sh::check_transfer_options(options); !ok) return bad_input("transfer", ok.error());
  auto run = run_transfer(scene, options, a.shape.no_cache, "sh transfer: vertices");
  if (!run) {
    fmt::print(stderr, "shaderbed: sh transfer: {}\n", run.error());
    return kExitFail;
  }
  const size_t rays = transfer_rays(scene, options);
  const size_t rays_cast = run->from_cache ? 0 : rays;
  const unsigned threads = worker_threads();
  const double per_second = run->from_cache || run->seconds <= 0 ? 0.0 : double(rays_cast) / run->seconds;
  const size_t shape_vertices = scene.meshes().front().positions.size();
  const size_t ground_vertices = scene.vertex_count() - shape_vertices;
  const size_t samples = size_t(a.shape.grid) * size_t(a.shape.grid);
  const std::string kind = options.kind == sh::TransferKind::interreflected
                               ? fmt::format("interreflected ({} bounce{})", options.bounces, options.bounces == 1 ? "" : "s")
                               : a.shape.kind;

  if (a.shape.json) {
    nlohmann::json j{{"shape", a.shape.shape},
                     {"tessellation", a.shape.slices > 0 ? nlohmann::json(nullptr) : nlohmann::json(a.shape.tessellation)},
                     {"slices", a.shape.slices > 0 ? nlohmann::json(a.shape.slices) : nlohmann::json(nullptr)},
                     {"ground", a.shape.ground},
                     {"kind", a.shape.kind},
                     {"bounces", options.bounces},
                     {"bands", a.bands},
                     {"coefficients_per_vertex", sh::coefficient_count(a.bands)},
                     {"grid", a.shape.grid},
                     {"samples_per_vertex", samples},
                     {"seed", a.shape.seed},
                     {"vertices", scene.vertex_count()},
                     {"shape_vertices", shape_vertices},
                     {"ground_vertices", ground_vertices},
                     {"rays", rays},
                     {"rays_cast", rays_cast},
                     {"seconds", run->seconds},
                     {"rays_per_second", run->from_cache ? nlohmann::json(nullptr) : nlohmann::json(per_second)},
                     {"threads", threads},
                     {"rays_per_second_per_core",
                      run->from_cache ? nlohmann::json(nullptr) : nlohmann::json(per_second / threads)},
                     {"from_cache", run->from_cache},
                     {"cache", run->cache},
                     {"cache_file", run->file.empty() ? nlohmann::json(nullptr) : nlohmann::json(run->file.string())},
                     {"computed_because", run->from_cache ? nlohmann::json(nullptr) : nlohmann::json(run->reason)}};
    if (a.coefficients) {
      // Per mesh (the shape, then the ground), per vertex, bands² RGB coefficients.
      nlohmann::json meshes = nlohmann::json::array();
      for (const sh::VertexTransfer& t : run->transfer) {
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
    fmt::print("{}\n", j.dump(2));
    return 0;
  }

  fmt::print("{}: {} vertices{}\n", shape_label(a.shape), scene.vertex_count(),
             ground_vertices ? fmt::format(" ({} shape + {} ground)", shape_vertices, ground_vertices) : "");
  fmt::print("{} transfer, {} bands ({} coefficients per channel), {} x {} = {} jittered rays per vertex, seed {}\n", kind,
             a.bands, sh::coefficient_count(a.bands), a.shape.grid, a.shape.grid, samples, a.shape.seed);
  if (run->from_cache) {
    fmt::print("read from the cache in {:.3f} s: {}\n", run->seconds, run->file.string());
    fmt::print("rays: {} when computed (none cast now)\n", rays);
  } else {
    fmt::print("computed in {:.3f} s ({}): {} rays cast", run->seconds, run->reason, rays_cast);
    if (rays_cast > 0)
      fmt::print(", {:.2f} M rays/s ({:.2f} M per core, {} core{})", per_second * 1e-6, per_second * 1e-6 / threads,
                 threads, threads == 1 ? "" : "s");
    fmt::print("\n");
    fmt::print("cache: {}{}\n", run->cache, run->file.empty() ? "" : ", stored in " + run->file.string());
  }
  if (a.coefficients)
    for (size_t m = 0; m < run->transfer.size(); ++m)
      for (size_t v = 0; v < run->transfer[m].vertex_count(); ++v) {
        std::string line = fmt::format("{} {}:", m == 0 ? "shape" : "ground", v);
        for (const glm::dvec3& x : run->transfer[m].vertex(v)) line += fmt::format(" ({:.6g} {:.6g} {:.6g})", x.r, x.g, x.b);
        fmt::print("{}\n", line);
      }
  return 0;
}

// ---- eval ---------------------------------------------------------------------------------

struct EvalArguments {
  ShapeArguments shape;
  std::string light = "directional";
  std::string probe, mapping = "latlong";
  std::vector<double> direction{0, 1, 0};
  double radius = 0.6;
  std::vector<int> bands_list;
  int bands = 0;
};

int run_eval(const EvalArguments& a) {
  if (a.shape.kind == "interreflected")
    return bad_input("eval", "--kind interreflected has no exact reference (its bounces are the approximation itself); "
                             "use unshadowed or shadowed");
  if (a.light == "probe" && a.probe.empty())
    return bad_input("eval", "--light probe needs --probe FILE (an .hdr or .exr environment map)");
  std::vector<int> bands_list = a.bands > 0 ? std::vector<int>{a.bands}
                                : a.bands_list.empty() ? std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8}
                                                       : a.bands_list;
  std::ranges::sort(bands_list);
  const auto [last, end] = std::ranges::unique(bands_list);
  bands_list.erase(last, end);
  const int max_bands = bands_list.back();

  // The light as an SH case's (prt/ShLight.h), not turned.
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
  if (!light) return bad_input("eval", a.light == "probe" ? naming(a.probe, light.error().message) : light.error().message);

  auto made = make_shape_scene(a.shape);
  if (!made) return bad_input("eval", made.error());
  const sh::TransferScene& scene = made->scene;
  const sh::TransferOptions options = transfer_options(a.shape, max_bands);
  if (auto ok = sh::check_transfer_options(options); !ok) return bad_input("eval", ok.error());
  auto run = run_transfer(scene, options, a.shape.no_cache, "sh eval: transfer");
  if (!run) {
    fmt::print(stderr, "shaderbed: sh eval: {}\n", run.error());
    return kExitFail;
  }

  // The exact integral at each of the shape's vertices (not the ground's), once.
  const sh::TransferMesh& mesh = scene.meshes().front();
  const sh::VertexTransfer& transfer = run->transfer.front();
  const size_t vertices = mesh.positions.size();
  const bool shadowed = options.kind != sh::TransferKind::unshadowed;
  std::vector<glm::dvec3> exact(vertices);
  const auto t0 = Clock::now();
  {
    Progress progress("sh eval: exact integral, vertices");
    std::atomic<size_t> done{0};
    parallel_for(vertices, [&](size_t v) {
      exact[v] = (*light)->exact_at(scene, mesh.positions[v], mesh.normals[v], mesh.albedo, shadowed);
      progress.update(++done, vertices);
    });
  }
  const double exact_seconds = seconds_since(t0);
  double max_exact = 0;
  for (const glm::dvec3& e : exact) max_exact = std::max(max_exact, max_component(e));

  struct Row {
    int bands;
    double max_abs, rms;
    size_t at;
  };
  std::vector<Row> rows;
  for (int bands : bands_list) {
    const std::vector<glm::dvec3> coefficients = (*light)->coefficients(bands);
    Row row{bands, 0.0, 0.0, 0};
    double squares = 0;
    for (size_t v = 0; v < vertices; ++v) {
      // Σ T_i L_i over the first bands² coefficients (the transfer's prefix: its bands are independent).
      const glm::dvec3 error = sh::shade(transfer, v, coefficients) - exact[v];
      squares += glm::dot(error, error);
      if (const double e = max_component(error); e > row.max_abs) row.max_abs = e, row.at = v;
    }
    row.rms = std::sqrt(squares / (3.0 * double(std::max<size_t>(vertices, 1))));
    rows.push_back(row);
  }

  const std::string exact_method =
      a.light == "directional"
          ? "the delta light in closed form (sh::exact_directional)"
          : fmt::format("Gauss-Legendre {} x {} quadrature of the light itself (sh::exact_diffuse_radiance)", kQuadratureTheta,
                        kQuadraturePhi);
  const std::string light_label =
      a.light == "directional" ? fmt::format("directional (D3DX normalisation) toward ({:g}, {:g}, {:g})", a.direction[0],
                                             a.direction[1], a.direction[2])
      : a.light == "cone"
          ? fmt::format("cone toward ({:g}, {:g}, {:g}), half-angle {:g} rad", a.direction[0], a.direction[1], a.direction[2],
                        a.radius)
      : a.light == "sky" ? std::string("the analytic sky")
                         : fmt::format("the environment map {} ({})", a.probe, a.mapping);

  if (a.shape.json) {
    nlohmann::json j{{"shape", a.shape.shape},
                     {"tessellation", a.shape.slices > 0 ? nlohmann::json(nullptr) : nlohmann::json(a.shape.tessellation)},
                     {"slices", a.shape.slices > 0 ? nlohmann::json(a.shape.slices) : nlohmann::json(nullptr)},
                     {"ground", a.shape.ground},
                     {"vertices", vertices},
                     {"kind", a.shape.kind},
                     {"light", a.light},
                     {"light_description", light_label},
                     {"grid", a.shape.grid},
                     {"samples_per_vertex", size_t(a.shape.grid) * size_t(a.shape.grid)},
                     {"seed", a.shape.seed},
                     {"transfer_bands", max_bands},
                     {"transfer_from_cache", run->from_cache},
                     {"transfer_seconds", run->seconds},
                     {"cache_file", run->file.empty() ? nlohmann::json(nullptr) : nlohmann::json(run->file.string())},
                     {"exact_method", exact_method},
                     {"exact_seconds", exact_seconds},
                     {"max_exact", max_exact}};
    nlohmann::json out = nlohmann::json::array();
    for (const Row& r : rows)
      out.push_back({{"bands", r.bands}, {"coefficients", sh::coefficient_count(r.bands)}, {"max_abs", r.max_abs},
                     {"rms", r.rms}, {"max_abs_vertex", r.at}});
    j["rows"] = std::move(out);
    fmt::print("{}\n", j.dump(2));
    return 0;
  }

  fmt::print("{}: {} vertices compared, {} transfer, {} x {} = {} jittered rays per vertex, seed {}\n",
             shape_label(a.shape), vertices, a.shape.kind, a.shape.grid, a.shape.grid,
             size_t(a.shape.grid) * size_t(a.shape.grid), a.shape.seed);
  fmt::print("transfer: {} bands, {} in {:.3f} s\n", max_bands,
             run->from_cache ? "read from the cache" : "computed (" + run->reason + ")", run->seconds);
  fmt::print("light: {}\n", light_label);
  fmt::print("exact: {}, same visibility, {:.3f} s; largest exact radiance {:.6g}\n", exact_method, exact_seconds, max_exact);
  fmt::print("\n{:>5} {:>12} {:>16} {:>16}\n", "bands", "coefficients", "max |SH-exact|", "RMS");
  for (const Row& r : rows)
    fmt::print("{:>5} {:>12} {:>16.4e} {:>16.4e}\n", r.bands, sh::coefficient_count(r.bands), r.max_abs, r.rms);
  return 0;
}

}  // namespace sh_command

Command add_sh_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "sh",
      "Spherical-harmonic precompute steps (book Ch. 8 and 9, docs/sh.md): project a light, compute a shape's "
      "per-vertex transfer, measure the SH approximation's error against the exact lighting integral");
  cmd->require_subcommand(1);

  // project
  auto p = std::make_shared<sh_command::ProjectArguments>();
  CLI::App* project = cmd->add_subcommand(
      "project",
      "Print a light's SH coefficients (index i = l(l+1)+m, l, m, value; RGB for lights, a scalar for the book's test "
      "function) by the book's jittered projection (grid x grid samples, 4 pi / N each) beside the exact ones (the "
      "lights' closed forms, or Gauss-Legendre for a map), and the largest differences. --light book --bands 5 --grid "
      "100 is the book's Fig. 8.14 example, printed with the values the book gives.");
  project->fallthrough();
  CLI::Option* light_option =
      project->add_option("--light", p->light,
                          "book (the test function of Figs. 8.13/8.14), directional, cone (D3DX semantics), sky (the "
                          "analytic sky) or probe (an environment map)")
          ->capture_default_str()
          ->check(CLI::IsMember({"book", "directional", "cone", "sky", "probe"}));
  CLI::Option* probe_option =
      project->add_option("--probe", p->probe, "The environment map of --light probe: .hdr, .exr or anything OpenImageIO reads");
  project->add_option("--mapping", p->mapping, "The probe's layout: latlong or angular (Debevec's light probe)")
      ->capture_default_str()
      ->check(CLI::IsMember({"latlong", "angular"}));
  project->add_option("--bands", p->bands, "Bands (bands² coefficients), 1 to 12")
      ->capture_default_str()
      ->check(CLI::Range(1, sh_command::kMaxBands));
  project->add_option("--grid", p->grid, "The jittered grid: grid x grid samples")
      ->capture_default_str()
      ->check(CLI::Range(1, sh_command::kMaxGrid));
  project->add_option("--seed", p->seed, "Seed of the jittered samples")->capture_default_str();
  project->add_option("--direction", p->direction,
                      "Toward the directional or cone light, x,y,z in the scene (y up; the default is the scene's light)")
      ->delimiter(',')
      ->expected(3)
      ->capture_default_str();
  project->add_option("--radius", p->radius, "The cone's half-angle in radians, 0 to pi")
      ->capture_default_str()
      ->check(CLI::Range(0.0, M_PI));
  project->add_flag("--exact", p->exact_only, "Only the exact coefficients (no jittered projection)");
  project->add_flag("--json", p->json, "Print JSON instead of text");

  // transfer
  auto t = std::make_shared<sh_command::TransferArguments>();
  CLI::App* transfer = cmd->add_subcommand(
      "transfer",
      "Compute a shape's per-vertex SH transfer (diffuse unshadowed, shadowed by Embree ray casts, or inter-reflected), "
      "or read it from the cache `shaderbed run` uses (<cache root>/sh); print the vertices, the rays cast, the time, "
      "rays per second, and whether it came from the cache. Progress goes to stderr.");
  transfer->fallthrough();
  sh_command::add_shape_options(transfer, t->shape, false);
  transfer->add_option("--bands", t->bands, "Bands of the transfer (bands² coefficients per channel), 1 to 12")
      ->capture_default_str()
      ->check(CLI::Range(1, sh_command::kMaxBands));
  transfer->add_flag("--coefficients", t->coefficients,
                     "Also print every vertex's coefficients (with --json: \"transfer\", per mesh, per vertex, "
                     "bands² [r, g, b])");

  // eval
  auto e = std::make_shared<sh_command::EvalArguments>();
  CLI::App* eval = cmd->add_subcommand(
      "eval",
      "For each band count, the error of per-vertex SH lighting over the shape's vertices: Σ T_i L_i in double (the "
      "jittered transfer, the light's coefficients) against the exact lighting integral with the same visibility (the "
      "delta in closed form for the directional light, Gauss-Legendre quadrature for the others); max abs and RMS "
      "over vertices and channels.");
  eval->fallthrough();
  sh_command::add_shape_options(eval, e->shape, true);
  eval->add_option("--light", e->light, "directional, cone, sky or probe")
      ->capture_default_str()
      ->check(CLI::IsMember({"directional", "cone", "sky", "probe"}));
  eval->add_option("--probe", e->probe, "The environment map of --light probe");
  eval->add_option("--mapping", e->mapping, "The probe's layout: latlong or angular")
      ->capture_default_str()
      ->check(CLI::IsMember({"latlong", "angular"}));
  eval->add_option("--direction", e->direction, "Toward the directional or cone light, x,y,z in the scene (y up)")
      ->delimiter(',')
      ->expected(3)
      ->capture_default_str();
  eval->add_option("--radius", e->radius, "The cone's half-angle in radians")
      ->capture_default_str()
      ->check(CLI::Range(0.0, M_PI));
  CLI::Option* list = eval->add_option("--bands-list", e->bands_list, "Band counts to compare, e.g. 1,2,4 (default 1,...,8)")
                          ->delimiter(',')
                          ->check(CLI::Range(1, sh_command::kMaxBands));
  eval->add_option("--bands", e->bands, "One band count instead, 1 to 12")->check(CLI::Range(1, sh_command::kMaxBands))->excludes(list);

  return {cmd, [p, t, e, project, transfer, eval, light_option, probe_option] {
            try {
              if (project->parsed()) {
                sh_command::ProjectArguments a = *p;
                if (probe_option->count() > 0 && light_option->count() == 0) a.light = "probe";
                if (!a.probe.empty() && a.light != "probe")
                  return sh_command::bad_input("project", "--probe is the map of --light probe, not of --light " + a.light);
                return sh_command::run_project(a);
              }
              if (transfer->parsed()) return sh_command::run_transfer_command(*t);
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
