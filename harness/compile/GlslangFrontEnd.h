#pragma once
// glslang front end: GLSL or DX9-style HLSL source to unvalidated SPIR-V.
#include <cstdint>
#include <vector>

#include "compile/Compiler.h"

namespace shaderbed {

// Binding numbers a stage's auto-mapped resources start from. GL has a single binding
// namespace for all stages, so HLSL vertex and pixel $Global blocks must not collide.
constexpr unsigned kFragmentBindingBase = 8;
// HLSL textures and sampler states start this far above their stage's base: the vertex
// stage's cbuffers take 0.., the fragment's 8.., textures 16.. and 24.., samplers 32.. and 40...
constexpr unsigned kTextureBindingOffset = 16;
constexpr unsigned kSamplerStateBindingOffset = 32;

// The first error of a glslang info log ("ERROR: file:LINE: message") as an Error; the
// file is the one the log names (an #include'd file or a #line marker's), else `path`.
Error glslang_log_error(const std::string& log, const std::string& path, const char* what);

// `read_files`, when given, receives every file the front end read besides `source`
// (#include files; an includer for HLSL/GLSL would report its files here too).
// `debug_info`: OpLine per instruction and OpName (and, for GLSL, the text in OpSource),
// which the shader's twin (twin/) reads to name source lines; drivers ignore them.
Result<std::vector<uint32_t>> glslang_to_spirv(Language language, const ShaderSource& source, Target target,
                                               std::vector<SourceFile>* read_files = nullptr, bool debug_info = false);

// Whether this process has started glslang (glslang::InitializeProcess, called on the
// first compile). A process served entirely by the compile cache never does.
bool glslang_initialised();

}  // namespace shaderbed
