#pragma once
// Unity ShaderLab (.shader): the first CGPROGRAM ... ENDCG (or HLSLPROGRAM ... ENDHLSL)
// block of the file is the program; its `#pragma vertex NAME` and `#pragma fragment NAME`
// name the entries. What glslang reads is the file with every line outside that block
// (and outside CGINCLUDE/HLSLINCLUDE blocks before it, which Unity puts in front of every
// program) and the two entry pragmas blanked, so line numbers stay the file's own and
// every message points into the .shader file. Includes (UnityCG.cginc, ...) are the
// user's own copies, found relative to the file or in the case's include_dirs; nothing
// is included implicitly. The text then goes through the Cg or HLSL path as any other.
// Not read: Properties (the case binds uniforms), SubShader tags, render states, passes
// after the first, multi_compile keywords (a case's defines select them).
#include <string>
#include <string_view>

#include "compile/Compiler.h"

namespace shaderbed {

// A .shader file, or a text that opens with `Shader "name"` (comments aside).
bool is_shaderlab_file(const std::string& path, std::string_view text);

struct ShaderLabProgram {
  std::string text;             // the file, blanked outside the program (same lines)
  bool hlsl_block = false;      // HLSLPROGRAM (else CGPROGRAM)
  std::string vertex_entry;     // from #pragma vertex; "" when the block has none
  std::string fragment_entry;   // from #pragma fragment
  int block_line = 0;           // of CGPROGRAM / HLSLPROGRAM
};

// The first program block; no block, an unterminated one, or a block without one of the
// entry pragmas is an error at the file's line.
Result<ShaderLabProgram> extract_shaderlab_program(std::string_view text, const std::string& path);

// Each stage of `program` that is a ShaderLab file becomes its program block; an entry
// the case leaves at "main" becomes the pragma's.
Result<ProgramSource> prepare_shaderlab_program(const ProgramSource& program);

}  // namespace shaderbed
