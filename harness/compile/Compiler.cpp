#include "compile/Compiler.h"

#include <fstream>
#include <map>
#include <sstream>

#include "compile/EffectFrontEnd.h"
#include "compile/GlslDialect.h"
#include "compile/GlslangFrontEnd.h"
#include "compile/ShaderFileText.h"
#include "compile/ShaderLabFrontEnd.h"
#include "compile/SourceDefines.h"
#include "compile/SpirvReflection.h"
#include "compile/SpirvTools.h"
#include "compile/StageCache.h"

namespace shaderbed {

const char* to_string(Language l) {
  switch (l) {
    case Language::glsl: return "glsl";
    case Language::hlsl: return "hlsl";
    case Language::cg: return "cg";
  }
  return "?";
}

const char* to_string(Stage s) { return s == Stage::vertex ? "vertex" : "fragment"; }

Result<ShaderSource> load_shader_source(Stage stage, const std::string& path) {
  auto text = read_shader_text(path, "shader file");
  if (!text) return std::unexpected(text.error());
  return ShaderSource{.stage = stage, .path = path, .text = std::move(*text)};
}

Result<ShaderModule> compile_stage(Language language, const ShaderSource& source, Target target,
                                   std::vector<SourceFile>* read_files) {
  // The Vulkan modules carry line information for the twin (twin/), which runs them. glslang
  // 12 sometimes emits invalid debug instructions (spirv-val: "Id is 0"): such a module is
  // compiled again without them, so the lines are lost but never the shader.
  const bool debug_info = target == Target::vulkan;
  auto spirv = glslang_to_spirv(language, source, target, read_files, debug_info);
  if (!spirv) return std::unexpected(spirv.error());
  if (auto ok = validate_spirv(*spirv, target, source.path); !ok) {
    if (!debug_info) return std::unexpected(ok.error());
    spirv = glslang_to_spirv(language, source, target, nullptr, false);
    if (!spirv) return std::unexpected(spirv.error());
    if (auto plain = validate_spirv(*spirv, target, source.path); !plain) return std::unexpected(plain.error());
  }
  auto reflection = reflect_spirv(*spirv, language, source.stage);
  if (!reflection) return std::unexpected(std::move(reflection.error()).in_file(source.path));
  auto driver_spirv = strip_reflection_info(*spirv, target);
  if (!driver_spirv) return std::unexpected(std::move(driver_spirv.error()).in_file(source.path));
  return ShaderModule{.stage = source.stage,
                      .source_file = source.path,
                      .entry_point = source.entry_point,
                      .spirv = std::move(*driver_spirv),
                      .reflection = std::move(*reflection)};
}

Result<CompiledProgram> compile_program(const ProgramSource& original, bool with_opengl) {
  // GLSL takes the case's defines in its text (SourceDefines.h): the native GL path, the
  // dialect layer and glslang then read the same source.
  ProgramSource source = original;
  if (source.language == Language::glsl)
    for (ShaderSource* stage : {&source.vertex, &source.fragment}) {
      stage->text = glsl_with_defines(stage->text, stage->defines);
      stage->defines.clear();
    }
  CompiledProgram out;
  out.language = source.language;
  // A DX9 effect becomes plain HLSL per stage (EffectFrontEnd.h); its pass's render
  // states, sampler_state settings and initial values travel with the program to the draw.
  // A Unity ShaderLab file's program block is Cg or HLSL like any other (ShaderLabFrontEnd.h).
  if (source.language != Language::glsl) {
    auto program = prepare_shaderlab_program(source);
    if (!program) return std::unexpected(program.error());
    source = std::move(*program);
  }
  Result<ProgramSource> rewritten = source;
  if (source.language == Language::hlsl)
    rewritten = prepare_effect_program(source, out);
  if (!rewritten) return std::unexpected(rewritten.error());
  // GLSL written for GL (legacy built-ins, varyings matched by name) becomes GLSL that
  // glslang compiles and links by location (GlslDialect.h); the native GL path keeps the
  // author's text.
  std::map<std::string, std::string> legacy_names;
  std::string native_vertex, native_fragment;
  if (source.language == Language::glsl) {
    auto glsl = prepare_glsl_program(source);
    if (!glsl) return std::unexpected(glsl.error());
    legacy_names = std::move(glsl->legacy_names);
    out.native_glsl_compatibility = glsl->compatibility;
    out.native_glsl_skip_reason = std::move(glsl->native_skip_reason);
    out.native_glsl_reduced_precision = glsl->native_reduced_precision;
    native_vertex = std::move(glsl->native_vertex);
    native_fragment = std::move(glsl->native_fragment);
    rewritten = std::move(glsl->program);
  }
  const ProgramSource& p = *rewritten;
  struct Job {
    const ShaderSource& src;
    Target target;
    ShaderModule& dst;
  };
  for (Job job : {Job{p.vertex, Target::vulkan, out.vertex}, Job{p.fragment, Target::vulkan, out.fragment},
                  Job{p.vertex, Target::opengl, out.vertex_gl}, Job{p.fragment, Target::opengl, out.fragment_gl}}) {
    if (job.target == Target::opengl && (!with_opengl || !out.opengl_skip_reason.empty())) continue;
    auto module = compile_stage_cached(p.language, job.src, job.target);
    // Vulkan GLSL the OpenGL target cannot take (push constants): the GL paths do not
    // apply, and the Vulkan one still runs.
    if (!module && job.target == Target::opengl && !out.native_glsl_skip_reason.empty()) {
      out.opengl_skip_reason = "Vulkan GLSL: the GL SPIR-V paths do not apply (" + module.error().to_string() + ")";
      continue;
    }
    if (!module) return std::unexpected(module.error());
    job.dst = std::move(*module);
    restore_legacy_names(job.dst.reflection, legacy_names);
  }
  if (!with_opengl || !out.opengl_skip_reason.empty()) return out;
  auto vs = spirv_to_glsl_cached(out.vertex_gl.spirv, Stage::vertex);
  if (!vs) return std::unexpected(std::move(vs.error()).in_file(p.vertex.path));
  auto fs = spirv_to_glsl_cached(out.fragment_gl.spirv, Stage::fragment);
  if (!fs) return std::unexpected(std::move(fs.error()).in_file(p.fragment.path));
  out.vertex_cross_glsl = std::move(*vs);
  out.fragment_cross_glsl = std::move(*fs);
  if (p.language == Language::glsl) {
    out.vertex_native_glsl = std::move(native_vertex);
    out.fragment_native_glsl = std::move(native_fragment);
  }
  return out;
}

}  // namespace shaderbed
