#pragma once
// The results model every report reads: one CellResult per case x variant x language x
// backend x path x shape, plus the toolchain that produced them. JSON (write and read),
// JUnit, HTML and the console table are views of this.
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shaderbed {

constexpr int kResultsSchemaVersion = 2;

// Per-image counts of values a lighting shader should not produce.
struct ValueCounts {
  size_t nan = 0;
  size_t pos_inf = 0;
  size_t neg_inf = 0;
  size_t negative = 0;     // finite and < 0
  size_t above_one = 0;    // finite and > 1 (legitimate for some models; reported, not judged)
};

struct CellMetrics {
  double max_abs = 0;               // interior
  double rmse = 0;                  // interior
  double psnr = 0;                  // interior, peak 1
  size_t bad_pixels = 0;            // interior + silhouette
  size_t nonfinite = 0;             // NaN/Inf in drawn pixels of the render
  size_t nonfinite_mismatch = 0;    // NaN/Inf where the reference is finite, or the reverse
  size_t coverage_mismatch = 0;
  double silhouette_max_abs = 0;
  size_t interior_pixels = 0;
  size_t silhouette_pixels = 0;
  size_t covered_pixels = 0;        // drawn by the render
  size_t reference_covered_pixels = 0;
  double expected_area = 0;         // the shape's projected area in pixels, from the mesh
  // The smallest thresholds that would have passed this cell (what tightening can reach).
  double min_passing_interior = 0;
  double min_passing_silhouette = 0;
  // The largest interior error as a share of its tolerance (max_abs + max_rel |reference|
  // per channel): over 1 fails. 0 in files from before it existed.
  double tolerance_share = 0;
  ValueCounts render_values;
  ValueCounts reference_values;
};

// What the error PNG's colours stand for (report/ErrorScale.h): 0 to `top`, the largest
// finite interior error or the interior threshold when that is larger, so every map has
// the threshold on its scale and its worst interior pixel at the top colour. `peak` is
// that largest error, at pixel (peak_x, peak_y) from the top left (-1: no interior pixel).
// top = 0: no map, or a results file from before the scale was recorded.
struct ErrorMapScale {
  double top = 0;
  double peak = 0;
  int peak_x = -1, peak_y = -1;
};

struct CellArtefacts {                // paths under the run's --out folder ("" = not written)
  std::string render_exr, render_png, error_exr, error_png, reference_png;
  std::string vertex_spirv, fragment_spirv;            // disassembly (.spvasm)
  std::string vertex_cross_glsl, fragment_cross_glsl;  // SPIRV-Cross output
  std::string stored_exr;                              // run --save-images: the image later runs compare with
  ErrorMapScale error_scale;                           // error_png's colours
};

// A median with its confidence interval (timing/MedianInterval).
struct TimingInterval {
  double median = 0;
  double low = 0;
  double high = 0;
  double level = 0;         // the interval's actual coverage, e.g. 0.96875 for 6 runs, 0.961 for 9
};

// The draw repeated (warm-up, then `runs` timed repeats), each repeat timed twice: by the
// driver's clock (Vulkan timestamp queries, GL_TIME_ELAPSED) and by the CPU's wall clock
// around submit + wait. On these CPU drivers the wall time is the honest cost; llvmpipe's
// GL_TIME_ELAPSED misses most of the rasteriser threads' work (docs/timing.md).
struct GpuTiming {
  std::string clock;        // "timestamp queries", "GL_TIME_ELAPSED"; "" = not timed
  int warmup = 0;
  int runs = 0;
  TimingInterval device;    // the driver's clock
  TimingInterval wall;      // CPU wall clock per repeat
};

// One named explanation of a failing cell's difference (compare/ConventionFit.h): the
// render fitted against the reference under a convention, and how well it fits.
struct Explanation {
  std::string name;          // stable id: "constant_factor", "extra_n_dot_l", ...
  std::string description;   // "× π (1/π normalisation)"
  double residual = 0;       // max |render - explained reference| over the fitted pixels
  double rmse = 0;
  size_t pixels = 0;         // pixels the fit used
  bool fits = false;         // within the interior tolerance
  std::string summary;       // the line a user reads: "matches the reference × π (1/π normalisation) to 2e-6"
};

// What a cell was judged against.
// How a cell ended. Strings only at the edges: reports print to_string, readers parse.
enum class CellStatus {
  pass,
  fail,
  error,
  skipped,   // the path does not apply; the message says why
};
const char* to_string(CellStatus);
std::optional<CellStatus> parse_cell_status(std::string_view text);

struct ReferenceSource {
  std::string kind;          // "model", "render" (the original on one backend/path) or "images" (a stored run)
  std::string label;         // "phong (per pixel)", "hlsl vulkan/spirv", "images in DIR"
  bool is_reference = false; // this cell's own render is the reference of its group
  std::string toolchain_note;   // images: how the stored run's toolchain differs from this one ("" = same)
};

struct CellResult {
  std::string case_name, variant, language, backend, path, shape;
  CellStatus status = CellStatus::error;
  std::string message;              // why it failed / the error line
  // Errors: the stage that refused the cell ("bind", "compile", "draw", ...; core/Error.h),
  // so a case's own mistake (an unbound uniform) can be told from a tool's failure.
  std::string error_stage;
  // Failures: which stage the evidence points at ("front end", "cross-compiler",
  // "driver", "model/reference", "unclear") and why; "" for passes.
  std::string attribution;
  std::string attribution_reason;
  // A failure listed in the expectations file: still "fail", but known, with its reason.
  bool known_failure = false;
  std::string known_reason;
  // What the reference did not see, e.g. the image files the case binds (the reference
  // models read no texture); "" when it saw everything the draw did.
  std::string reference_note;
  // Not failures: what the case says that the shader ignores, e.g. a [bindings.<lang>]
  // entry naming a uniform or register the shader's reflection does not declare.
  std::vector<std::string> warnings;
  CellMetrics metrics;
  double interior_threshold = 0;    // the case's tolerance (absolute part)
  double silhouette_threshold = 0;
  double interior_threshold_rel = 0;     // relative part: a channel may differ by abs + rel |reference|
  double silhouette_threshold_rel = 0;
  std::string tolerance_reason;          // why the interior tolerance is what it is
  ReferenceSource reference;
  // Failures: the convention fits, the ones that fit first (best first); empty for passes.
  std::vector<Explanation> explanations;
  double lut_bound = 0;             // LUT variants: the derived LUT error bound in the threshold
  std::string lut_derivation;
  double texel_bound = 0;           // differential cells sampling 8-bit textures: the derived texel-step bound in it
  std::string texel_derivation;
  // SH cases (harness/prt): the cell is judged against the truncated SH in double (the
  // shader's own error); against the exact lighting integral the error adds the
  // approximation's, which is bounded separately. Absent for other cases.
  struct ShErrors {
    std::string summary;           // light, bands, transfer, rays per vertex
    double render_vs_exact = -1;   // max |render - exact| over covered pixels (-1: no exact reference)
    double rmse_vs_exact = -1;     // its RMS over the same pixels and channels
    double truncation = -1;        // max |truncated SH in double - exact|: the approximation's own
    double bound = -1;             // the case's [tolerance] approximation (-1: none)
    double precompute_ms = 0;      // transfer, projection, CPCA (0 from the cache)
    double bytes_per_vertex = 0;   // the per-vertex streams
  };
  std::optional<ShErrors> sh;
  // --twin: the render against the same shader executed by its twin (twin/) in the run's
  // precision, i.e. this render's own fp32 + driver error (for --twin half: what a device
  // honouring RelaxedPrecision would change); with a model or original reference, also the
  // twin against that reference, i.e. what the shader's formula differs by. Absent
  // without --twin.
  struct TwinFigures {
    std::string precision;            // "double", "float", "half"
    double max_abs = -1, rmse = -1;   // render vs twin, per channel over the twin's interior
    int worst_x = -1, worst_y = -1;   // where max_abs is (row 0 at the top)
    double share = 0;                 // largest |render - twin| / the cell's interior tolerance there
    double reference_max_abs = -1;    // twin vs the cell's reference over its interior (-1: none)
    // The double twin's own error at the worst pixel: its colour against both stages run
    // again there in quad precision (-1: not checked, i.e. not a double twin).
    double self_error = -1;
    double ms = 0;                    // the twin's draw, every core
    std::string precision_note;       // --twin half, beyond the tolerance: which lines are reduced
    std::string nonfinite_origin;     // a non-finite pixel: the instruction that first made NaN/Inf
    std::string error;                // why there are no figures ("" = there are)
  };
  std::optional<TwinFigures> twin;
  // A failing cell of a port: the line where it departs from what it is judged against
  // (twin/Divergence.h), found by matching the port's values to the original's or the
  // model's over a few dozen pixels. Absent when the cell did not fail or has no twin to ask.
  struct Divergence {
    std::string kind;                 // "found", "output_matches", "unlocalised", "error"
    std::string against;              // "the original", "the model"
    std::string stage, file;          // stage: "fragment" or "vertex"
    int line = 0;
    std::string source, operation, value;
    struct Operand {
      std::string name, matches;      // matches: the counterpart's label, "constant" or ""
    };
    std::vector<Operand> operands;
    std::string nearest_file, nearest_value, nearest_relation;   // nearest_file "": none
    int nearest_line = 0;
    std::string text;                 // the one line the console prints
    int pixels = 0;
    // The lines around it in the shader, and around the original's nearest value (or the
    // first operand's match), for a report to show side by side; `mark` is highlighted.
    struct Excerpt {
      std::string file;
      int first = 0, mark = 0;        // line numbers
      std::vector<std::string> lines;
    };
    Excerpt port_source, original_source;
    std::string error;                // kind "error": why it could not be localised
  };
  std::optional<Divergence> divergence;
  // CPU wall times: compile, build, draw, readback, reference, compare, and io (writing the
  // cell's images, with --out only). "compile" is the
  // cell's program's (shared by every cell of that case/variant/language) and "reference"
  // its group's (case/variant/shape): sum them once each (bench/SuiteCost does). "build"
  // is the driver's pipeline/program build + JIT, 0 when the backend reused the pipeline
  // of an earlier cell with the same program (program_cached).
  std::map<std::string, double> time_ms;
  bool program_cached = false;
  GpuTiming gpu;
  std::string vertex_spirv_hash, fragment_spirv_hash;   // hex FNV-1a 64 of the driver SPIR-V
  // Hex FNV-1a 64 of what the image depends on besides the shaders: size, camera, lights,
  // the case's parameters, light and ambient, the mesh. Stored images are matched on it.
  std::string scene_hash;
  // Function-body instructions of the driver SPIR-V (stats::count_spirv), per stage.
  int vertex_instructions = 0, fragment_instructions = 0;
  CellArtefacts artefacts;

  std::string id() const {          // stable identity: sharding, expectations, merging
    return case_name + "/" + variant + "/" + language + "/" + backend + "/" + path + "/" + shape;
  }
};

struct ToolVersions {
  std::string glslang, spirv_tools, spirv_cross, vulkan_driver, gl_driver, llvm;
  std::string vulkan_device;   // the device the Vulkan cells ran on (--vulkan-device), with its type
  // How the GL cells reached GL (--gl-platform, --gl-device): "osmesa", "egl surfaceless",
  // "egl device 0: ..."; "" when no GL cell ran.
  std::string gl_platform;
};

// The caches a run used, and how the compile cache answered (docs/caches.md). Caches
// never change a result; this says why a run was quick, or why it was not.
struct CacheUse {
  bool driver_cache = false;          // Mesa's disk shader cache on
  std::string driver_cache_dir;       // the folder Mesa uses ("" when off)
  bool compile_cache = false;         // shaderbed's disk compile cache on
  std::string compile_cache_dir;      // "" when off
  size_t compile_hits = 0;            // compiles answered without running a compiler (memory or disk)
  size_t compile_misses = 0;          // compiles that ran glslang + SPIRV-Tools, or SPIRV-Cross
  size_t compile_memory_hits = 0;     // of the hits, from this process's own memory
};

// A run that did not finish: it was interrupted (SIGINT, SIGTERM) and wrote the cells it had.
struct Interruption {
  int signal = 0;          // 2 SIGINT, 15 SIGTERM
  std::string reason;      // "interrupted by SIGINT after 120 of 1400 cells"
};

struct RunReport {
  ToolVersions tools;
  // Which run the results belong to: a hash of the options that decide the pixels and the
  // verdicts and of the compilers, not of the cell filters or the shard, so the jobs of a CI
  // matrix and the shards of a run share it and `merge` refuses results of different runs.
  // "" in files from before it existed.
  std::string run_id;
  // Each selected case's name -> hex FNV-1a 64 of its case file: two parts that ran one
  // case must have read the same file.
  std::map<std::string, std::string> case_digests;
  std::optional<Interruption> interruption;   // set when the run did not finish
  std::optional<CacheUse> cache;    // absent in merged reports and in files from before it existed
  std::vector<CellResult> results;
  double wall_ms = 0;
  int workers = 1;                  // worker threads that ran the cells (run --jobs)
  std::string out_dir;
  std::string keep_images;          // which cells' images out_dir has (CellSettings::keep_images); "" = unknown
  std::string shard;                // "I/N" when this is one shard of a run, else ""
  std::string stored_images_lost;   // why --save-images saved nothing (a full disk...); "" = saved or not asked

  size_t count(CellStatus status) const {
    size_t n = 0;
    for (const CellResult& r : results) n += r.status == status;
    return n;
  }
  // Every cell passed or is a known failure, and the run finished.
  bool acceptable() const {
    if (interruption) return false;
    for (const CellResult& r : results)
      if (r.status != CellStatus::pass && r.status != CellStatus::skipped && !(r.status == CellStatus::fail && r.known_failure)) return false;
    return true;
  }
};

// Whether a stage's time is shared by the cells of a program (its compile, its reference
// image) rather than the cell's own.
inline bool shared_stage(const std::string& stage) { return stage == "compile" || stage == "reference"; }

// A cell's own time: its stages' milliseconds without the shared ones.
inline double own_ms(const CellResult& r) {
  double ms = 0;
  for (const auto& [stage, t] : r.time_ms)
    if (!shared_stage(stage) && std::isfinite(t)) ms += t;
  return ms;
}

}  // namespace shaderbed
