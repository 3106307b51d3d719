#include <cstring>

#include <fmt/format.h>

#include "backends/Backend.h"

namespace shaderbed {
namespace {

void append(std::string& key, const std::string& text) {
  key += std::to_string(text.size());
  key += ':';
  key += text;
}

void append(std::string& key, const ShaderModule& module) {
  append(key, module.entry_point);
  std::string words(module.spirv.size() * sizeof(uint32_t), '\0');
  // A native-GLSL module has no SPIR-V: memcpy from its null data is undefined even for 0 bytes.
  if (!words.empty()) std::memcpy(words.data(), module.spirv.data(), words.size());
  append(key, words);
  // The reflection decides how attributes, uniforms and samplers are fed (attributes by
  // semantic, which stripped SPIR-V may not carry), so it is part of what was built.
  const Reflection& r = module.reflection;
  for (const StageInput& input : r.inputs)
    append(key, fmt::format("in {} {} {} {}", input.location, input.name, input.semantic, input.components));
  for (const UniformBlock& block : r.uniform_blocks) {
    append(key, fmt::format("block {} {} {} {}", block.name, block.set, block.binding, block.size));
    for (const UniformMember& m : block.members)
      append(key, fmt::format("{} {} {} {} {} {} {} {} {} {}", m.name, m.offset, m.size, m.is_float, m.vecsize,
                              m.columns, m.matrix_stride, m.column_registers, m.array_size, m.array_stride));
  }
  for (const SamplerBinding& sampler : r.samplers)
    append(key, fmt::format("sampler {} {} {} {}", sampler.name, sampler.set, sampler.binding, sampler.dimensions));
}

}  // namespace

std::string program_key(const CompiledProgram& program, ShaderPath path, const RenderState& state) {
  // Full content rather than a hash: a cache hit must never be a collision.
  std::string key = to_string(path);
  key += '|';
  append(key, describe(state));
  switch (path) {
    case ShaderPath::spirv:
      // One key per target: Vulkan draws the Vulkan modules, GL the GL-target ones; a
      // backend only ever looks up its own.
      append(key, program.vertex);
      append(key, program.fragment);
      append(key, program.vertex_gl);
      append(key, program.fragment_gl);
      break;
    case ShaderPath::native_glsl:
      append(key, program.vertex_native_glsl);
      append(key, program.fragment_native_glsl);
      break;
    case ShaderPath::cross_glsl:
      append(key, program.vertex_cross_glsl);
      append(key, program.fragment_cross_glsl);
      // The layout check and uniform packing read the GL reflection.
      append(key, program.vertex_gl);
      append(key, program.fragment_gl);
      break;
  }
  return key;
}

}  // namespace shaderbed
