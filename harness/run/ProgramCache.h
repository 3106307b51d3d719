#pragma once
// A case variant's program in one language, compiled once per worker and shared by every
// cell (and every hard-case row) that draws it: the compiled stages, what compiling cost,
// the SPIR-V instruction counts, and (with an output folder) the disassembly written for
// the reports. Compile errors are kept too, so a broken shader is reported once per cell
// without being recompiled. The cache is bounded (LruCache.h): a case with thousands of
// variants recompiles an evicted program rather than holding every one.
#include <cstddef>
#include <string>
#include <utility>

#include "compile/Compiler.h"
#include "run/LruCache.h"
#include "report/Results.h"
#include "scene/CaseFile.h"

namespace shaderbed {

struct CachedProgram {
  Result<CompiledProgram> program = fail(ErrorStage::compile, "not compiled");
  double ms = 0;                             // load + compile + count, for time_ms.compile
  CellArtefacts sources;                     // disassembly and cross GLSL paths ("" without an out folder)
  std::pair<int, int> instructions{0, 0};    // SPIR-V totals: vertex, fragment
};

struct ProgramOptions {
  bool relaxed_precision = false;   // floats declared relaxed (compile/RelaxedPrecision.h)
  std::string out_dir;              // "" = write no artefacts
  bool opengl = true;               // false: Vulkan-target modules only (no GL cell will draw them)
  // A worker runs a bundle's programs again and again, one case after another: a few
  // hundred entries keep every program of a group warm; the bytes bound huge shaders.
  size_t max_programs = 256;
  size_t max_bytes = size_t(256) << 20;
};

// Not thread-safe: one per worker (the compile stage below it is shared and thread-safe).
class ProgramCache {
 public:
  explicit ProgramCache(ProgramOptions options)
      : options_(std::move(options)), programs_(options_.max_programs, options_.max_bytes) {}
  // Valid until the next get() (an evicted entry is freed only when another is added).
  const CachedProgram& get(const Case& c, const Variant& variant, Language language);

  size_t size() const { return programs_.size(); }
  size_t bytes() const { return programs_.bytes(); }
  size_t evictions() const { return programs_.evictions(); }

 private:
  ProgramOptions options_;
  LruCache<CachedProgram> programs_;   // case/variant/language
};

}  // namespace shaderbed
