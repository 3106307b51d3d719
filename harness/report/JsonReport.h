#pragma once
#include <cstddef>
#include <string>
#include <string_view>

#include "core/Error.h"
#include "report/Results.h"

namespace shaderbed {

// The results file, schema version kResultsSchemaVersion (2). Every field of RunReport is
// written, always (empty strings and zeros included), so write -> read -> write is exact:
//
// {"schema": 2,
//  "tools": {"glslang", "spirv_tools", "spirv_cross", "llvm", "mesa": {"vulkan", "gl"},
//            "vulkan_device", "gl_platform"},   ("tool" before; still read; no gl_platform before EGL)
//  "run_id": "...", "shard": "I/N" or "", "out_dir": "...", "wall_ms": 1234.5, "workers": 2,
//  "cases": {"phong": "<hex digest of its case file>", ...},
//  "cache": {"driver": {"enabled", "dir"}, "compile": {"enabled", "dir", "hits", "misses",
//            "memory_hits"}},   (run only; a folder under $HOME is written "~/...")
//  "incomplete": {"signal": 2, "reason": "interrupted by SIGINT after 120 of 1400 cells"},   (only when so)
//  "totals": {"cells", "pass", "fail", "known", "error", "skipped"},        (derived; ignored on read)
//  "results": [{
//    "id": "case/variant/language/backend/path/shape",               (derived; ignored on read)
//    "case", "variant", "language", "backend", "path", "shape",
//    "status": "pass" | "fail" | "error", "message": "...",
//    "attribution": {"verdict": "driver" | ... | "", "reason": "..."},
//    "known_failure": {"known": bool, "reason": "..."},
//    "warnings": ["..."],                  (not failures: e.g. a binding the shader does not declare)
//    "reference": {"kind": "model" | "render" | "images", "label", "is_reference": bool,
//                  "toolchain_note"},              (what the cell was judged against)
//    "explanations": [{"name", "description", "summary", "residual", "rmse", "pixels",
//                      "fits": bool}],              (convention fits of a failure, fitting first)
//    "metrics": {"max_abs", "rmse", "psnr", "bad_pixels", "nonfinite", "nonfinite_mismatch",
//                "coverage_mismatch", "silhouette_max_abs",
//                "min_passing": {"interior", "silhouette"}, "tolerance_share",
//                "coverage": {"interior_pixels", "silhouette_pixels", "covered_pixels",
//                             "reference_covered_pixels", "expected_area"},
//                "values": {"render": {"nan", "pos_inf", "neg_inf", "negative", "above_one"},
//                           "reference": {...same...}}},
//    "tolerance": {"interior", "silhouette", "interior_rel", "silhouette_rel", "reason",
//                  "lut": {"bound", "derivation"}},   (a channel passes within abs + rel |reference|)
//    "time_ms": {"compile": ..., "build": ..., ...},      (CPU wall times; build 0 when cached)
//    "program_cached": bool,                   (the backend reused an earlier cell's pipeline)
//    "gpu_ms": {"clock": "timestamp queries" | "GL_TIME_ELAPSED" | "", "warmup", "runs",
//               "device": {"median", "ci": {"low", "high", "level"}},   (driver's clock)
//               "wall": {...same...}},                                  (CPU clock per repeat)
//    "spirv_hash": {"vertex", "fragment"}, "scene_hash": "...",
//    "instructions": {"vertex", "fragment"},   (SPIR-V function-body instructions as drawn)
//    "artefacts": {"render_exr", "render_png", "error_exr", "error_png", "reference_png",
//                  "stored_exr", "vertex_spirv", "fragment_spirv", "vertex_cross_glsl",
//                  "fragment_cross_glsl",
//                  "error_scale": {"top", "peak", "peak_x", "peak_y"}},   (with an error map only:
//                  its colours run from 0 to top; peak: the worst interior error, at peak_x, peak_y)
//    "image": render_exr                      (v1 alias, only when set; ignored on read)
//  }]}
//
// JSON has no Inf/NaN: a non-finite number is written as the string "inf", "-inf" or "nan"
// (psnr is +inf for identical images); the reader also takes null as NaN.
std::string to_json(const RunReport& report);
// The same on one line (no newline in it): the message an isolated worker sends per cell.
std::string to_json_line(const RunReport& report);
Result<void> write_json(const RunReport& report, const std::string& path);

// The largest results file read, far above what a run of the whole library writes.
constexpr size_t kMaxResultsBytes = size_t(256) << 20;

// Reads a results file written by write_json (any shard); only a regular file of at most
// kMaxResultsBytes. Errors name the file and, for
// syntax errors, the line and column; for a wrong field, its JSON pointer. A schema version
// other than kResultsSchemaVersion is refused.
Result<RunReport> read_json(const std::string& path);
// The same from text; `file` only names the source in errors.
Result<RunReport> parse_json(std::string_view text, const std::string& file);

}  // namespace shaderbed
