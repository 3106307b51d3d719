#pragma once
// Driver instruction counts: the NIR Mesa actually compiles for a program, per stage.
//
// Mesa reads its debug environment once, when the driver loads, so the driver runs in a
// child process: the helper executable shaderbed-nir-dump compiles the program's source
// files, builds and draws it once on one backend with the capture environment set, and
// exits; this side reads what the driver wrote and counts it (NirText.h).
//
// Methods (Mesa 22.3.6, Debian 12; see tests/nir and the report):
//   gallium_trace  GALLIUM_TRACE=<file> GALLIUM_TRACE_NIR=<big>: the trace driver wraps the
//                  gallium screen and writes the NIR handed to create_{vs,fs}_state.
//                  lavapipe (Vulkan) and OSMesa or EGL (GL): the NIR llvmpipe compiles.
//                  Works on lavapipe and on EGL. On OSMesa the helper hangs with
//                  GALLIUM_TRACE set (measured on 22.3.6), so it is refused with an
//                  error, not run.
//   glsl_dump      MESA_GLSL=dump, shader cache disabled, on stderr (GL only): prints the
//                  GLSL IR and then the NIR of each linked stage (all three GL paths), on
//                  OSMesa and on EGL alike: it is Mesa's GL front end, not the platform's.
//   automatic      gallium_trace on Vulkan, glsl_dump on GL (both platforms alike).
#include <string>

#include "pipeline/ShaderPath.h"
#include "compile/ShaderModule.h"
#include "core/Error.h"
#include "stats/nir/NirText.h"

namespace shaderbed {

enum class NirBackend { vulkan, gl };
enum class NirMethod { automatic, gallium_trace, glsl_dump };   // automatic: what works on the backend
const char* to_string(NirBackend);
const char* to_string(NirMethod);

struct NirProgramCounts {
  NirCounts vertex;
  NirCounts fragment;
  std::string method;   // e.g. "gallium_trace on lavapipe"
  const NirCounts& operator[](Stage s) const { return s == Stage::vertex ? vertex : fragment; }
};

struct NirRequest {
  NirBackend backend = NirBackend::vulkan;
  ShaderPath path = ShaderPath::spirv;   // GL: spirv, native_glsl or cross_glsl; Vulkan: spirv
  NirMethod method = NirMethod::automatic;
  std::string gl_platform = "osmesa";    // GL: --gl-platform and --gl-device for the helper
  std::string gl_device;
  std::string helper;                    // the helper binary; empty: find it (see nir_dump_helper)
};

// The helper: $SHADERBED_NIR_DUMP if set, else the path CMake built, else
// "shaderbed-nir-dump" beside the running executable.
std::string nir_dump_helper();

// Counts for both stages of a program compiled from its source files
// (program.vertex.source_file / fragment.source_file are recompiled in the child, so
// they must be readable files). An error saying "counts unavailable: <method>: <why>"
// when the method gives no NIR on this driver, never zeros.
Result<NirProgramCounts> nir_counts(const CompiledProgram& program, const NirRequest& request);

// One stage.
Result<NirCounts> nir_counts(const CompiledProgram& program, Stage stage, const NirRequest& request);

}  // namespace shaderbed
