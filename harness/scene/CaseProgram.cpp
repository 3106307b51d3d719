#include "scene/CaseProgram.h"

namespace shaderbed {

Result<ProgramSource> load_case_program(Language language, const ShaderFiles& files, const std::string& case_path) {
  auto missing = [&](const std::string& file) {
    return std::unexpected(Error{.message = "shader file not found: " + file, .file = case_path, .line = files.line,
                                 .stage = ErrorStage::case_file});
  };
  auto vs = load_shader_source(Stage::vertex, files.vertex);
  if (!vs) return missing(files.vertex);
  auto fs = load_shader_source(Stage::fragment, files.fragment);
  if (!fs) return missing(files.fragment);
  vs->entry_point = files.vertex_entry;
  fs->entry_point = files.fragment_entry;
  for (ShaderSource* stage : {&*vs, &*fs}) {
    stage->defines = files.defines;
    stage->include_dirs = files.include_dirs;
  }
  return ProgramSource{language, std::move(*vs), std::move(*fs)};
}

}  // namespace shaderbed
