#pragma once
// Front ends (glslang: GLSL, HLSL in the book's DX9 style) to validated SPIR-V for the
// Vulkan and OpenGL targets, with reflection, plus SPIRV-Cross GLSL for the GL path.
#include <string>
#include <utility>
#include <vector>

#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed {

enum class Target { vulkan, opengl };

// A preprocessor macro the case defines for a shader (`defines = { HAS_NORMALS = "1" }`):
// name and replacement text, in the order they are defined.
using Define = std::pair<std::string, std::string>;

struct ShaderSource {
  Stage stage = Stage::vertex;
  std::string path;        // for error messages and #include resolution
  std::string text;
  std::string entry_point = "main";
  std::vector<Define> defines;            // defined before the first line (compile/SourceDefines.h)
  std::vector<std::string> include_dirs;  // absolute; searched after the including file's folder
};

// A file a compile read besides its ShaderSource (an #include), with the exact text read.
// The disk compile cache keeps these and checks them on every hit (CompileCache.h).
struct SourceFile {
  std::string path;
  std::string text;
  bool operator==(const SourceFile&) const = default;
};

// A DX9 effect's technique and pass ("" = the first), and where the case names them,
// for the error when the effect has no such technique or pass (compile/EffectFrontEnd.h).
struct EffectChoice {
  std::string technique;
  std::string pass;
  std::string named_in;  // the case file
  int line = 0;
};

struct ProgramSource {
  Language language = Language::glsl;
  ShaderSource vertex;
  ShaderSource fragment;
  EffectChoice effect;   // used when a stage's file is an effect (.fx, or technique blocks)
};

// Reads a file into a ShaderSource (error with the path when it cannot be read).
Result<ShaderSource> load_shader_source(Stage stage, const std::string& path);

// One stage to SPIR-V for one target; validated with spirv-val; reflection filled in.
// Uncached. `read_files`, when given, receives every other file the compile read (the Cg
// front end's #include files, in the order read).
Result<ShaderModule> compile_stage(Language language, const ShaderSource& source, Target target,
                                   std::vector<SourceFile>* read_files = nullptr);

// Both stages, both targets, and the SPIRV-Cross GLSL of the OpenGL-target modules;
// through the compile caches (StageCache.h), so a warm process does not run a compiler.
// with_opengl = false: only the Vulkan-target modules, for runs that draw nothing on GL
// (no GL-target SPIR-V, no SPIRV-Cross GLSL: half the compiles of a cold one-cell run).
Result<CompiledProgram> compile_program(const ProgramSource& program, bool with_opengl = true);

// Human-readable SPIR-V disassembly (for reports and debugging).
std::string disassemble(const std::vector<uint32_t>& spirv);

}  // namespace shaderbed
