#pragma once
// Compiles every selected case x variant x language and counts both stages.
#include <functional>
#include <string>
#include <vector>

#include "compile/Compiler.h"
#include "stats/StatsReport.h"

namespace shaderbed::stats {

struct StatsOptions {
  std::string cases_dir;
  std::vector<std::string> cases, variants, languages;   // empty = all
  bool nir = true;   // also read the driver's NIR (one child process per program and backend)
  // How the NIR helper reaches GL: --gl-platform and --gl-device (backends/Backend.h's
  // GlPlatformChoice, spelled out: stats sits below the backends).
  std::string gl_platform = "osmesa";
  std::string gl_device;
  // Called after each step (a program compiled and counted; one backend's NIR read) from
  // the calling thread: `what` names it ("phong/pixel/hlsl", "phong/pixel/hlsl NIR vulkan").
  std::function<void(size_t done, size_t total, const std::string& what)> on_step;
};

// Counts of one compiled program's two stages (Vulkan-target SPIR-V, as compiled, -O, -Os).
Result<StatsEntry> stage_stats(const CompiledProgram& program, Stage stage);

// Every entry; a shader that does not compile is an entry with `error` set. Unknown names
// in the filters are an Error.
Result<StatsReport> collect_stats(const StatsOptions& options);

}  // namespace shaderbed::stats
