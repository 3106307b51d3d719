#pragma once
// The glslang side of the Cg dialect (see CgDialect.h for the passes): the includer,
// preprocessing, and the checks that need glslang's AST. GlslangFrontEnd calls these
// three hooks for Language::cg and otherwise treats Cg as HLSL.
#include <string>

#include "compile/CgDialect.h"
#include "compile/Compiler.h"

namespace glslang {
class TShader;
}

namespace shaderbed {

// What glslang's HLSL front end parses in place of the author's Cg.
struct CgPrepared {
  std::string text;      // preprocessed, translated; #line markers name the author's files
  std::string preamble;  // macros and the helpers the text calls
  CgTranslation translation;
  std::vector<CgNote> notes;  // every pass's notes (pragmas, includes, rewrites)
  std::vector<SourceFile> includes;  // every file #include read, as read (the compile cache checks them)
};

// Passes 1-3: each file prepared, includes resolved relative to the including file
// (`#include "file"`; `#pragma once` honoured), glslang's preprocessor, translation.
// Errors carry the file and line they are in, also inside included files.
Result<CgPrepared> prepare_cg(const ShaderSource& source, Target target);

// After a successful parse: Cg constructs glslang accepts with a different meaning.
// Today: the depth-compare lookup form (tex2D(sampler2D, float3), ...), which glslang
// silently truncates to a plain lookup.
Result<void> check_cg_ast(glslang::TShader& shader, const std::string& path);

}  // namespace shaderbed
