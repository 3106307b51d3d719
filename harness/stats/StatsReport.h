#pragma once
// The result of `shaderbed stats`: one entry per case x variant x language x stage, with
// SPIR-V counts as compiled, after spirv-opt -O and -Os, and the SPIRV-Cross GLSL size.
// JSON layout: {"tools": {...}, "entries": [{"case", "variant", "language",
// "stage", "spirv": {...}, "spirv_opt": {...}, "spirv_os": {...}, "glsl_lines", "nir",
// "book"}]}. Each counts object also carries "extended_calls" ({"Pow": 1, ...}).
#include <cstddef>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/Error.h"
#include "stats/SpirvCounts.h"

namespace shaderbed::stats {

// Driver (Mesa NIR) counts: filled by the NIR reader; absent = "nir": null.
struct NirCounts {
  int alu = 0, tex = 0, control = 0;
};
struct NirStats {
  std::optional<NirCounts> vulkan;   // lavapipe
  std::optional<NirCounts> gl;       // OSMesa or EGL (--gl-platform)
  std::string note;                  // why a reading is missing with this Mesa, if it is
};

struct StatsEntry {
  std::string case_name, variant, language, stage;   // stage: "vertex" | "fragment"
  ClassCounts spirv, spirv_opt, spirv_os;
  int glsl_lines = 0;               // SPIRV-Cross GLSL (from the OpenGL-target module)
  std::optional<NirStats> nir;
  std::optional<int> book;          // the book's DX9 ps_2_0/vs_1_1 slot count, if quoted
  std::string error;                // compile failure (then the counts are zero)

  std::string key() const { return case_name + "/" + variant + "/" + language + "/" + stage; }
};

struct StatsReport {
  std::map<std::string, std::string> tool;   // glslang, spirv_tools, spirv_cross, spirv_grammar
  std::vector<StatsEntry> entries;
};

std::string to_json(const StatsReport&);
Result<StatsReport> from_json(const std::string& text);
// The largest stats JSON read, far above what `stats` writes for the whole library.
constexpr size_t kMaxStatsBytes = size_t(256) << 20;
// Reads a `stats --json` file: only a regular file of at most kMaxStatsBytes; errors name it.
Result<StatsReport> read_stats_json(const std::string& path);
Result<void> write_text_file(const std::string& path, const std::string& text);

std::string to_csv(const StatsReport&);

enum class TableForm {
  compact,   // fits 120 columns: one row per case/variant/stage/language, the main counts
  wide,      // every class count, one column block per language side by side (~230 columns)
};
// Aligned table of the counts with a legend, then the GLSL.std.450 calls after -O.
// compact: SPIR-V total and its arithmetic/extended/texture/control parts, the totals after
// -O and -Os, the SPIRV-Cross GLSL lines, the NIR ALU counts on lavapipe and OSMesa/EGL and the
// book's count; wide: also memory/conversion/other and the -O class counts.
std::string format_table(const StatsReport&, TableForm form = TableForm::compact);
// The compact table's promise: no line of it is wider than this.
constexpr size_t kCompactTableWidth = 120;

// The book's quoted instruction count for a case/variant/stage, if it gives one
// (its §3.26). Not the same instruction set: for orientation.
std::optional<int> book_count(const std::string& case_name, const std::string& variant, const std::string& stage);

}  // namespace shaderbed::stats
