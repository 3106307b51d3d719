#include "backends/gl/SpirvUniformLocations.h"

#include <map>

#include "backends/gl/GlError.h"
#include "pipeline/SpirvWords.h"

namespace shaderbed::gl {
namespace {

std::string describe(const SpirvUniformLocation& u) {
  std::string text = u.name.empty() ? "an unnamed uniform" : "'" + u.name + "'";
  if (u.binding >= 0) text += " (binding " + std::to_string(u.binding) + ")";
  return text;
}

}  // namespace

std::vector<SpirvUniformLocation> spirv_uniform_locations(const std::vector<uint32_t>& spirv) {
  std::map<uint32_t, std::string> names;
  std::map<uint32_t, uint32_t> locations, bindings;
  std::vector<uint32_t> uniform_constants;
  for (const SpirvInstruction in : SpirvInstructions(spirv)) {
    const std::span<const uint32_t> w = in.words;
    if (in.opcode == spv::Op::OpName && w.size() >= 3) names[w[1]] = spirv_literal_string(w.subspan(2));
    if (in.opcode == spv::Op::OpDecorate && w.size() >= 4) {
      if (w[2] == std::to_underlying(spv::Decoration::Location)) locations[w[1]] = w[3];
      if (w[2] == std::to_underlying(spv::Decoration::Binding)) bindings[w[1]] = w[3];
    }
    if (in.opcode == spv::Op::OpVariable && w.size() >= 4 &&
        w[3] == std::to_underlying(spv::StorageClass::UniformConstant))
      uniform_constants.push_back(w[2]);
  }
  std::vector<SpirvUniformLocation> result;
  for (uint32_t id : uniform_constants) {
    const auto location = locations.find(id);
    if (location == locations.end()) continue;
    const auto binding = bindings.find(id);
    result.push_back({.location = location->second,
                      .name = names.contains(id) ? names[id] : std::string(),
                      .binding = binding == bindings.end() ? -1 : int64_t(binding->second)});
  }
  return result;
}

Result<void> check_uniform_locations_across_stages(const CompiledProgram& program) {
  const auto vertex = spirv_uniform_locations(program.vertex_gl.spirv);
  const auto fragment = spirv_uniform_locations(program.fragment_gl.spirv);
  for (const SpirvUniformLocation& v : vertex)
    for (const SpirvUniformLocation& f : fragment) {
      if (v.location != f.location || (v.name == f.name && v.binding == f.binding)) continue;
      return std::unexpected(
          gl_error("the vertex shader's " + describe(v) + " and the fragment shader's " + describe(f) +
                   " both have uniform location " + std::to_string(v.location) +
                   " in the OpenGL SPIR-V; GL would link them as one uniform (the compile stage must give each "
                   "stage its own uniform location range)")
              .in_file(program.fragment.source_file));
    }
  return {};
}

}  // namespace shaderbed::gl
