#include "compile/GlslangFrontEnd.h"

#include <atomic>
#include <mutex>
#include <optional>
#include <regex>
#include <sstream>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include "compile/CgFrontEnd.h"
#include "compile/HlslGuards.h"

namespace shaderbed {
namespace {

std::atomic<bool> initialised{false};

void initialise_glslang_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    glslang::InitializeProcess();
    initialised = true;
  });
}

EShLanguage to_glslang(Stage stage) { return stage == Stage::vertex ? EShLangVertex : EShLangFragment; }

// DX9 HLSL as the book writes it: POSITION is the clip-space output of a vertex shader,
// which glslang only knows as SV_Position (without this it becomes a plain varying).
// A vertex shader's SV_Position *input* stays an ordinary attribute, and a pixel
// shader's becomes the fragment coordinate, as VPOS was.
constexpr const char* kHlslPreamble =
    "#define POSITION SV_Position\n"
    "#define SHADERBED 1\n";

std::string missing_entry_message(const ShaderSource& source) {
  return std::string("no ") + to_string(source.stage) + " entry point '" + source.entry_point +
         "' in this file (the case's " + to_string(source.stage) + "_entry names it; default main)";
}

}  // namespace

// glslang's info log: "ERROR: file:LINE: message" (possibly several). Take the first
// error and keep the rest in the message so nothing is lost.
Error glslang_log_error(const std::string& log, const std::string& path, const char* what) {
  static const std::regex first_error(R"((?:ERROR|error): ([^:\n]*):(\d+): ([^\n]*))");
  Error e{.message = std::string(what) + " failed", .file = path, .stage = "compile"};
  std::smatch m;
  if (std::regex_search(log, m, first_error)) {
    if (!m[1].str().empty()) e.file = m[1].str();   // an included file, or a #line marker's
    e.line = std::stoi(m[2].str());
    e.message = m[3].str();
    // Count the other errors so a cascade is visible without flooding the line.
    int total = 0;
    for (auto it = std::sregex_iterator(log.begin(), log.end(), first_error); it != std::sregex_iterator(); ++it)
      ++total;
    if (total > 1) e.message += " (+" + std::to_string(total - 1) + " more errors)";
  } else if (!log.empty()) {
    std::string first_line = log.substr(0, log.find('\n'));
    e.message += ": " + first_line;
  }
  return e;
}

bool glslang_initialised() { return initialised; }

Result<std::vector<uint32_t>> glslang_to_spirv(Language language, const ShaderSource& source, Target target,
                                               std::vector<SourceFile>* read_files) {
  initialise_glslang_once();
  const EShLanguage stage = to_glslang(source.stage);
  const bool hlsl = language != Language::glsl;

  // Cg: the dialect layer's translation (CgDialect.h) is what glslang's HLSL front end reads.
  std::optional<CgPrepared> cg;
  if (language == Language::cg) {
    auto prepared = prepare_cg(source, target);
    if (!prepared) return std::unexpected(prepared.error());
    cg = std::move(*prepared);
    if (read_files) read_files->insert(read_files->end(), cg->includes.begin(), cg->includes.end());
  }
  if (language == Language::hlsl)
    if (auto ok = reject_glslang_crashers(source); !ok) return std::unexpected(ok.error());
  const std::string& source_text = cg ? cg->text : source.text;

  glslang::TShader shader(stage);
  const char* text = source_text.c_str();
  const int length = static_cast<int>(source_text.size());
  const char* name = source.path.c_str();
  shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
  shader.setEntryPoint(source.entry_point.c_str());
  shader.setSourceEntryPoint(source.entry_point.c_str());

  const glslang::EShClient client = target == Target::vulkan ? glslang::EShClientVulkan : glslang::EShClientOpenGL;
  shader.setEnvInput(hlsl ? glslang::EShSourceHlsl : glslang::EShSourceGlsl, stage, client, 100);
  if (target == Target::vulkan)
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
  else
    shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);

  int messages = EShMsgSpvRules;
  if (target == Target::vulkan) messages |= EShMsgVulkanRules;
  if (hlsl) {
    messages |= EShMsgReadHlsl | EShMsgHlslOffsets | EShMsgHlslDX9Compatible | EShMsgHlslLegalization;
    shader.setPreamble(cg ? cg->preamble.c_str() : kHlslPreamble);
    shader.setHlslIoMapping(true);
    // Keep semantics (POSITION, NORMAL, TEXCOORDn) in the SPIR-V so vertex inputs can be
    // matched to mesh attributes by meaning, not by declaration order.
    shader.setEnvTargetHlslFunctionality1();
  }
  // Resources without explicit bindings get bindings; HLSL stages get distinct ones (see header).
  shader.setAutoMapBindings(true);
  shader.setAutoMapLocations(true);
  // Only HLSL/Cg: shifts apply to explicit bindings too, and a GLSL author's
  // layout(binding = N) must reach the driver as written.
  if (hlsl && source.stage == Stage::fragment) {
    for (auto res : {glslang::EResSampler, glslang::EResTexture, glslang::EResImage, glslang::EResUbo,
                     glslang::EResSsbo, glslang::EResUav})
      shader.setShiftBinding(res, kFragmentBindingBase);
  }
  // GL-target SPIR-V gives loose uniforms (samplers) locations, counted from 0 in each
  // stage: a program sampling in both stages would collide, so fragments start at 64.
  if (target == Target::opengl && source.stage == Stage::fragment) shader.setUniformLocationBase(64);

  const auto msgs = static_cast<EShMessages>(messages);
  if (!shader.parse(GetDefaultResources(), 100, false, msgs))
    return std::unexpected(glslang_log_error(shader.getInfoLog(), source.path, "parse"));
  if (cg)
    if (auto ok = check_cg_ast(shader, source.path); !ok) return std::unexpected(ok.error());

  glslang::TProgram program;
  program.addShader(&shader);
  // glslang reports a missing entry function only as a linker warning ("Entry point not
  // found"), without its name: say which function the file lacks and where it comes from.
  const auto missing_entry = [&](const char* log) -> std::optional<Error> {
    if (std::string(log).find("Entry point not found") == std::string::npos) return std::nullopt;
    return Error{.message = missing_entry_message(source), .file = source.path, .stage = "compile"};
  };
  if (!program.link(msgs)) {
    if (auto e = missing_entry(program.getInfoLog())) return std::unexpected(*e);
    return std::unexpected(glslang_log_error(program.getInfoLog(), source.path, "link"));
  }
  if (!program.mapIO()) {
    if (auto e = missing_entry(program.getInfoLog())) return std::unexpected(*e);
    return std::unexpected(glslang_log_error(program.getInfoLog(), source.path, "I/O mapping"));
  }

  std::vector<uint32_t> spirv;
  spv::SpvBuildLogger logger;
  glslang::SpvOptions options;
  options.disableOptimizer = !hlsl;   // HLSL needs glslang's legalisation passes
  options.validate = false;           // we run spirv-val ourselves with the right env
  glslang::GlslangToSpv(*program.getIntermediate(stage), spirv, &logger, &options);
  const std::string log = logger.getAllMessages();
  if (spirv.empty())
    return std::unexpected(Error{.message = "SPIR-V generation failed: " + log, .file = source.path, .stage = "compile"});
  if (cg)
    if (auto ok = assign_cg_varying_locations(spirv, source.stage, cg->translation, source.path); !ok)
      return std::unexpected(ok.error());
  return spirv;
}

}  // namespace shaderbed
