#pragma once
// Reads the shader files a case names for one variant and language. A missing file is
// reported at the case file's line that names it.
#include "compile/Compiler.h"
#include "scene/CaseFile.h"

namespace shaderbed {

Result<ProgramSource> load_case_program(Language language, const ShaderFiles& files, const std::string& case_path);

}  // namespace shaderbed
