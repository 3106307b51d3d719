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
#include "compile/GlslProfile.h"
#include "compile/HlslGuards.h"
#include "compile/HlslIncluder.h"
#include "compile/HlslIntrinsics.h"
#include "compile/SourceDefines.h"

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

// Loose uniforms' block per stage: vertex and fragment blocks must not share a binding
// (GL has one namespace for all stages), and authors' own blocks start from 0.
constexpr unsigned kGlslDefaultBlockBinding = 14;

void relax_vulkan_rules(glslang::TShader& shader, Stage stage) {
  shader.setEnvInputVulkanRulesRelaxed();
  shader.setGlobalUniformSet(0);
  shader.setGlobalUniformBinding(kGlslDefaultBlockBinding + (stage == Stage::fragment ? 1 : 0));
}

// glslang's #version messages carry no line: give them the directive's.
void place_version_error(Error& e, const std::string& text) {
  if (e.line != 0 || !e.message.starts_with("#version")) return;
  const GlslVersion version = glsl_version(text);
  if (version.declared) e.line = version.line;
}

std::string missing_entry_message(const ShaderSource& source) {
  return std::string("no ") + to_string(source.stage) + " entry point '" + source.entry_point +
         "' in this file (the case's " + to_string(source.stage) + "_entry names it; default main)";
}

}  // namespace

// glslang's info log: "ERROR: file:LINE: message" (possibly several). Take the first
// error and keep the rest in the message so nothing is lost. An error without a place
// comes first when it is the cause (glslang's "#version: ..." message), so it is kept.
Error glslang_log_error(const std::string& log, const std::string& path, const char* what) {
  static const std::regex first_error(R"((?:ERROR|error): ([^:\n]*):(\d+): ([^\n]*))");
  static const std::regex unplaced_error(R"((?:^|\n)ERROR: (#[^\n]*))");
  Error e{.message = std::string(what) + " failed", .file = path, .stage = ErrorStage::compile};
  std::smatch m;
  if (std::regex_search(log, m, unplaced_error)) {
    e.message = m[1].str();
    const auto located = std::sregex_iterator(log.begin(), log.end(), first_error);
    const auto others = std::distance(located, std::sregex_iterator());
    if (others > 0) e.message += " (+" + std::to_string(others) + " more errors)";
  } else if (std::regex_search(log, m, first_error)) {
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
                                               std::vector<SourceFile>* read_files, bool debug_info) {
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

  // GLSL written for GL declares loose uniforms (`uniform mat4 model;`): glslang's relaxed
  // Vulkan rules gather them into one block per stage (gl_DefaultUniformBlock), bound like
  // any other block. The GL target takes the same rules (its SPIR-V is valid for both).
  const bool relaxed = language == Language::glsl && needs_relaxed_vulkan_rules(source_text);
  const bool vulkan_rules = target == Target::vulkan || relaxed;
  const glslang::EShClient client = vulkan_rules ? glslang::EShClientVulkan : glslang::EShClientOpenGL;
  shader.setEnvInput(hlsl ? glslang::EShSourceHlsl : glslang::EShSourceGlsl, stage, client, 100);
  if (relaxed) relax_vulkan_rules(shader, source.stage);
  if (vulkan_rules)
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
  else
    shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);

  // HLSL's preamble with the case's defines, or the Cg layer's (which has them already),
  // and the intrinsics glslang gets wrong routed to correct ones (HlslIntrinsics.h; Cg's
  // layer substitutes its own lit).
  const std::string preamble =
      hlsl ? (cg ? cg->preamble : std::string(kHlslPreamble) + define_lines(source.defines)) +
                 hlsl_intrinsic_corrections(source_text, HlslIntrinsicSet{.lit = !cg})
           : std::string();
  int messages = EShMsgSpvRules;
  if (vulkan_rules) messages |= EShMsgVulkanRules;
  if (hlsl) {
    messages |= EShMsgReadHlsl | EShMsgHlslOffsets | EShMsgHlslDX9Compatible | EShMsgHlslLegalization;
    shader.setPreamble(preamble.c_str());
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
  // SM4+ numbers cbuffers (bN), textures (tN) and sampler states (sN) in separate register
  // spaces, so b0, t0 and s0 must not land on one binding: each type gets its own range
  // per stage (glslang counts DX9's sampler2D as a texture).
  if (hlsl) {
    const unsigned base = source.stage == Stage::fragment ? kFragmentBindingBase : 0;
    shader.setShiftBinding(glslang::EResTexture, base + kTextureBindingOffset);
    shader.setShiftBinding(glslang::EResSampler, base + kSamplerStateBindingOffset);
  }
  // GL-target SPIR-V gives loose uniforms (samplers) locations, counted from 0 in each
  // stage: a program sampling in both stages would collide, so fragments start at 64.
  if (target == Target::opengl && source.stage == Stage::fragment) shader.setUniformLocationBase(64);
  // GL_ARB_gl_spirv has no separate samplers: an SM4 Texture2D sampled with a
  // SamplerState becomes one sampler2D named after the texture (the Vulkan target keeps
  // both; CaseTextures gives the texture its sampler state's settings).
  if (hlsl && target == Target::opengl)
    shader.setTextureSamplerTransformMode(EShTexSampTransUpgradeTextureRemoveSampler);

  const auto msgs = static_cast<EShMessages>(messages);
  // HLSL #include, relative to the including file, then the case's include_dirs (HlslIncluder.h); the files it reads go
  // to read_files for the disk cache. Cg's includes were resolved by prepare_cg.
  std::vector<SourceFile> hlsl_includes;
  HlslIncluder hlsl_includer(hlsl_includes, source.include_dirs);
  glslang::TShader::ForbidIncluder no_includer;
  glslang::TShader::Includer& includer =
      language == Language::hlsl ? static_cast<glslang::TShader::Includer&>(hlsl_includer) : no_includer;
  const bool parsed = shader.parse(GetDefaultResources(), 100, false, msgs, includer);
  if (read_files) read_files->insert(read_files->end(), hlsl_includes.begin(), hlsl_includes.end());
  if (!parsed) {
    Error e = glslang_log_error(shader.getInfoLog(), source.path, "parse");
    if (language == Language::glsl) place_version_error(e, source_text);
    return std::unexpected(std::move(e));
  }
  if (cg)
    if (auto ok = check_cg_ast(shader, source.path); !ok) return std::unexpected(ok.error());

  glslang::TProgram program;
  program.addShader(&shader);
  // glslang reports a missing entry function only as a linker warning ("Entry point not
  // found"), without its name: say which function the file lacks and where it comes from.
  const auto missing_entry = [&](const char* log) -> std::optional<Error> {
    if (std::string(log).find("Entry point not found") == std::string::npos) return std::nullopt;
    return Error{.message = missing_entry_message(source), .file = source.path, .stage = ErrorStage::compile};
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
  options.generateDebugInfo = debug_info;
  glslang::GlslangToSpv(*program.getIntermediate(stage), spirv, &logger, &options);
  const std::string log = logger.getAllMessages();
  if (spirv.empty())
    return std::unexpected(Error{.message = "SPIR-V generation failed: " + log, .file = source.path, .stage = ErrorStage::compile});
  if (cg)
    if (auto ok = assign_cg_varying_locations(spirv, source.stage, cg->translation, source.path); !ok)
      return std::unexpected(ok.error());
  return spirv;
}

}  // namespace shaderbed
