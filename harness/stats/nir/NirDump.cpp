#include "stats/nir/NirDump.h"

#include <unistd.h>   // environ (glibc declares it with _GNU_SOURCE, which g++ and clang++ set)

#include <cstdlib>
#include <filesystem>
#include <vector>

#include "core/ThisExecutable.h"
#include "core/ChildProcess.h"
#include "core/ScratchDirectory.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

std::string tail(const std::string& s, size_t n) { return s.size() <= n ? s : "..." + s.substr(s.size() - n); }

// Environment of the child: ours minus any Mesa capture settings, plus the method's.
std::vector<std::string> child_environment(NirMethod method, const fs::path& trace) {
  std::vector<std::string> env;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string_view v(*e);
    if (v.starts_with("GALLIUM_TRACE") || v.starts_with("MESA_GLSL=") || v.starts_with("MESA_SHADER_CACHE") ||
        v.starts_with("NIR_DEBUG="))
      continue;
    env.emplace_back(v);
  }
  env.emplace_back("MESA_SHADER_CACHE_DISABLE=true");
  if (method == NirMethod::gallium_trace) {
    env.emplace_back("GALLIUM_TRACE=" + trace.string());
    env.emplace_back("GALLIUM_TRACE_NIR=1000000");
  } else {
    env.emplace_back("MESA_GLSL=dump");
  }
  return env;
}

const char* language_name(Language l) { return to_string(l); }

// "lavapipe", "OSMesa llvmpipe", "EGL surfaceless llvmpipe", "EGL device 1".
std::string driver_name(const NirRequest& request) {
  if (request.backend == NirBackend::vulkan) return "lavapipe";
  if (request.gl_platform == "osmesa") return "OSMesa llvmpipe";
  if (request.gl_device.empty()) return "EGL surfaceless llvmpipe";
  return "EGL device " + request.gl_device;
}

}  // namespace

const char* to_string(NirBackend b) { return b == NirBackend::vulkan ? "vulkan" : "gl"; }
const char* to_string(NirMethod m) {
  switch (m) {
    case NirMethod::automatic: return "automatic";
    case NirMethod::gallium_trace: return "gallium_trace";
    case NirMethod::glsl_dump: return "glsl_dump";
  }
  return "?";
}

std::string nir_dump_helper() {
  if (const char* env = std::getenv("SHADERBED_NIR_DUMP"); env != nullptr && *env != '\0') return env;
#ifdef SHADERBED_NIR_DUMP_BINARY
  if (fs::exists(SHADERBED_NIR_DUMP_BINARY)) return SHADERBED_NIR_DUMP_BINARY;
#endif
  const fs::path self = this_executable();
  return self.empty() ? std::string("shaderbed-nir-dump") : (self.parent_path() / "shaderbed-nir-dump").string();
}

Result<NirProgramCounts> nir_counts(const CompiledProgram& program, const NirRequest& given) {
  NirRequest request = given;
  if (request.method == NirMethod::automatic)
    request.method = request.backend == NirBackend::vulkan ? NirMethod::gallium_trace : NirMethod::glsl_dump;
  const std::string driver = driver_name(request);
  const std::string what = std::string("counts unavailable: ") + to_string(request.method) + " on " + driver;
  auto unavailable = [&](const std::string& why) { return fail(ErrorStage::nir, what + ": " + why); };

  if (request.backend == NirBackend::vulkan && request.method == NirMethod::glsl_dump)
    return unavailable("MESA_GLSL=dump is a GL (GLSL compiler) setting; Vulkan has no GLSL linker");
  if (request.backend == NirBackend::gl && request.gl_platform == "osmesa" && request.method == NirMethod::gallium_trace)
    return unavailable("with GALLIUM_TRACE set, OSMesa never finishes the draw on Mesa 22.3.6 (measured: the "
                       "trace stops after context_create and the process hangs); use glsl_dump, or --gl-platform egl");
  if (request.backend == NirBackend::vulkan && request.path != ShaderPath::spirv)
    return unavailable("Vulkan takes SPIR-V only");
  for (const ShaderModule* m : {&program.vertex, &program.fragment})
    if (m->source_file.empty() || !fs::exists(m->source_file))
      return unavailable("the helper recompiles from source files, and '" + m->source_file + "' is not a readable file");

  auto dir = ScratchDirectory::create("nir");
  if (!dir) return unavailable(dir.error().message);
  const fs::path trace = dir->path() / "trace.xml";

  const std::string helper = request.helper.empty() ? nir_dump_helper() : request.helper;
  const std::vector<std::string> args = {helper,
                                         "--backend", to_string(request.backend),
                                         "--path", to_string(request.path),
                                         "--lang", language_name(program.language),
                                         "--vertex", program.vertex.source_file,
                                         "--fragment", program.fragment.source_file,
                                         "--vertex-entry", program.vertex.entry_point,
                                         "--fragment-entry", program.fragment.entry_point,
                                         "--gl-platform", request.gl_platform,
                                         "--gl-device", request.gl_device};
  auto exit = run_child(args, dir->path(), ErrorStage::nir, child_environment(request.method, trace));
  if (!exit) return unavailable("cannot run the helper '" + helper + "': " + exit.error().message);
  const std::string& stderr_text = exit->stderr_text;
  if (!exit->succeeded())
    return fail(ErrorStage::nir, "the NIR helper failed (" + exit->how() + "): " + tail(exit->stdout_text + stderr_text, 600));

  std::vector<NirShader> shaders;
  if (request.method == NirMethod::gallium_trace) {
    if (!fs::exists(trace)) return unavailable("the driver wrote no trace file (GALLIUM_TRACE not honoured)");
    shaders = nir_from_gallium_trace(read_text_file(trace));
    if (shaders.empty())
      return unavailable("the trace holds no NIR shaders (GALLIUM_TRACE_NIR not honoured, or the driver was not given NIR)");
  } else {
    shaders = nir_from_printed_text(stderr_text);
    if (shaders.empty())
      return unavailable("MESA_GLSL=dump printed no NIR on stderr (this Mesa prints " +
                         std::string(stderr_text.find("GLSL IR for") != std::string::npos ? "GLSL IR only"
                                                                                          : "nothing recognisable") +
                         ")");
  }

  // The program's own shaders are the first vertex and fragment shaders printed: they
  // are built (linked, pipeline created) before the draw, and the internal shaders a
  // driver makes while drawing (OSMesa's st prints one for glClear's
  // gl_CurrentAttribFrag2MESA) come after.
  NirProgramCounts result;
  result.method = std::string(to_string(request.method)) + " on " + driver;
  for (Stage stage : {Stage::vertex, Stage::fragment}) {
    const NirShader* found = nullptr;
    for (const NirShader& s : shaders)
      if (s.stage == stage && found == nullptr) found = &s;
    if (found == nullptr) return unavailable(std::string("no ") + to_string(stage) + " shader NIR in the capture");
    auto counts = count_nir(found->text);
    if (!counts) return unavailable(counts.error().message);
    (stage == Stage::vertex ? result.vertex : result.fragment) = *counts;
  }
  return result;
}

Result<NirCounts> nir_counts(const CompiledProgram& program, Stage stage, const NirRequest& request) {
  auto all = nir_counts(program, request);
  if (!all) return std::unexpected(all.error());
  return (*all)[stage];
}

}  // namespace shaderbed
