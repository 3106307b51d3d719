#include "run/ProgramArtefacts.h"

#include "core/AtomicFile.h"
#include "core/Fnv1a.h"

#include <filesystem>

#include <fmt/format.h>

#include "compile/Compiler.h"

namespace shaderbed {
namespace {

// Checked and flushed like every artefact (core/AtomicFile.h): a full disk is an error.
Result<void> write_text(const std::string& path, const std::string& text) {
  return write_file_atomically(path, text, "SPIR-V listing");
}

}  // namespace

std::string spirv_hash(const std::vector<uint32_t>& spirv) { return hex64(fnv1a64(spirv)); }

Result<void> write_program_artefacts(const std::string& dir, const CompiledProgram& p, CellArtefacts& out) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const std::string stem = (std::filesystem::path(dir) / to_string(p.language)).string();
  // A listing that could not be written is not named: no report links a missing file.
  Result<void> all;
  const auto put = [&all](std::string& field, const std::string& path, const std::string& text) {
    const Result<void> written = write_text(path, text);
    field = written ? path : "";
    if (!written && all) all = written;
  };
  put(out.vertex_spirv, stem + ".vert.spvasm", disassemble(p.vertex.spirv));
  put(out.fragment_spirv, stem + ".frag.spvasm", disassemble(p.fragment.spirv));
  // A Vulkan-only run compiles no GL target, so there is no SPIRV-Cross GLSL to show.
  if (p.vertex_cross_glsl.empty()) return all;
  put(out.vertex_cross_glsl, stem + ".vert.cross.glsl", p.vertex_cross_glsl);
  put(out.fragment_cross_glsl, stem + ".frag.cross.glsl", p.fragment_cross_glsl);
  return all;
}

}  // namespace shaderbed
