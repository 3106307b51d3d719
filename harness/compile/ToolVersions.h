#pragma once
#include <string>

namespace shaderbed {

struct CompilerVersions {
  std::string glslang, spirv_tools, spirv_cross;
};

// Versions of the compilers linked into this build, recorded in every result. Reads
// version constants only: it does not start glslang.
CompilerVersions compiler_versions();

// A hash, generated at build time (StageFingerprint.cmake), of shaderbed's compile stage:
// every harness/compile/*.h and *.cpp, and the compiler libraries linked in (glslang,
// SPIRV-Tools, SPIRV-Cross). Part of every compile cache key, so a change to the Cg
// dialect, a front-end option or a Debian rebuild of glslang can never serve stale SPIR-V.
std::string compile_stage_fingerprint();

}  // namespace shaderbed
