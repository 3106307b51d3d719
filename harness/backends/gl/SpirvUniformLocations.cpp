#include "backends/gl/SpirvUniformLocations.h"

#include <cstring>
#include <map>

#include "backends/gl/GlError.h"

namespace shaderbed::gl {
namespace {

constexpr uint32_t op_name = 5;
constexpr uint32_t op_variable = 59;
constexpr uint32_t op_decorate = 71;
constexpr uint32_t decoration_location = 30;
constexpr uint32_t decoration_binding = 33;
constexpr uint32_t storage_uniform_constant = 0;
constexpr size_t header_words = 5;

std::string literal_string(const uint32_t* words, size_t count) {
  const auto* chars = reinterpret_cast<const char*>(words);
  return std::string(chars, strnlen(chars, count * sizeof(uint32_t)));
}

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
  for (size_t at = header_words; at < spirv.size();) {
    const uint32_t word_count = spirv[at] >> 16;
    const uint32_t opcode = spirv[at] & 0xffff;
    if (word_count == 0 || at + word_count > spirv.size()) break;
    const uint32_t* operands = &spirv[at + 1];
    if (opcode == op_name && word_count >= 3) names[operands[0]] = literal_string(operands + 1, word_count - 2);
    if (opcode == op_decorate && word_count >= 4) {
      if (operands[1] == decoration_location) locations[operands[0]] = operands[2];
      if (operands[1] == decoration_binding) bindings[operands[0]] = operands[2];
    }
    if (opcode == op_variable && word_count >= 4 && operands[2] == storage_uniform_constant)
      uniform_constants.push_back(operands[1]);
    at += word_count;
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
