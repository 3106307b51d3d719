#pragma once
// A case variant's program in one language, compiled once per worker and shared by every
// cell (and every hard-case row) that draws it: the compiled stages, what compiling cost,
// the SPIR-V instruction counts, and (with an output folder) the disassembly written for
// the reports. Compile errors are kept too, so a broken shader is reported once per cell
// without being recompiled.
#include <map>
#include <string>
#include <utility>

#include "compile/Compiler.h"
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
};

// Not thread-safe: one per worker (the compile stage below it is shared and thread-safe).
class ProgramCache {
 public:
  explicit ProgramCache(ProgramOptions options) : options_(std::move(options)) {}
  const CachedProgram& get(const Case& c, const Variant& variant, Language language);

 private:
  ProgramOptions options_;
  std::map<std::string, CachedProgram> programs_;   // case/variant/language
};

}  // namespace shaderbed
