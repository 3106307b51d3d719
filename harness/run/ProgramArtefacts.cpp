#include "run/ProgramArtefacts.h"

#include "core/Fnv1a.h"

#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "compile/Compiler.h"

namespace shaderbed {
namespace {

Result<void> write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) return std::unexpected(Error{.message = "cannot write", .file = path, .stage = ErrorStage::report});
  return {};
}

}  // namespace

std::string spirv_hash(const std::vector<uint32_t>& spirv) { return hex64(fnv1a64(spirv)); }

Result<void> write_program_artefacts(const std::string& dir, const CompiledProgram& p, CellArtefacts& out) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const std::string stem = (std::filesystem::path(dir) / to_string(p.language)).string();
  out.vertex_spirv = stem + ".vert.spvasm";
  out.fragment_spirv = stem + ".frag.spvasm";
  for (auto written : {write_text(out.vertex_spirv, disassemble(p.vertex.spirv)),
                       write_text(out.fragment_spirv, disassemble(p.fragment.spirv))})
    if (!written) return written;
  // A Vulkan-only run compiles no GL target, so there is no SPIRV-Cross GLSL to show.
  if (p.vertex_cross_glsl.empty()) return {};
  out.vertex_cross_glsl = stem + ".vert.cross.glsl";
  out.fragment_cross_glsl = stem + ".frag.cross.glsl";
  for (auto written : {write_text(out.vertex_cross_glsl, p.vertex_cross_glsl),
                       write_text(out.fragment_cross_glsl, p.fragment_cross_glsl)})
    if (!written) return written;
  return {};
}

}  // namespace shaderbed
