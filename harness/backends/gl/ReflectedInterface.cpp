// The program interface from the compile stage's reflection (SPIR-V and SPIRV-Cross
// GLSL paths), and the check that SPIRV-Cross kept the reflected layout.
#include <algorithm>
#include <string>

#include "backends/gl/GlError.h"
#include "backends/gl/GlProgramInterface.h"

namespace shaderbed::gl {
namespace {

bool same_layout(const UniformBlock& a, const UniformBlock& b) {
  return a.name == b.name && a.size == b.size &&
         std::ranges::equal(a.members, b.members, [](const UniformMember& x, const UniformMember& y) {
           return x.name == y.name && x.offset == y.offset && x.size == y.size && x.vecsize == y.vecsize &&
                  x.columns == y.columns && x.matrix_stride == y.matrix_stride &&
                  x.column_registers == y.column_registers && x.array_size == y.array_size &&
                  x.array_stride == y.array_stride && x.is_float == y.is_float;
         });
}

std::string describe(const UniformBlock& block, Stage stage) {
  return "'" + block.name + "' (" + to_string(stage) + " shader)";
}

}  // namespace

Result<GlProgramInterface> interface_from_reflection(const CompiledProgram& program) {
  GlProgramInterface result;
  std::vector<Stage> block_stage;
  for (const ShaderModule* module : {&program.vertex_gl, &program.fragment_gl}) {
    for (UniformBlock block : module->reflection.uniform_blocks) {
      // The declared size can stop short of a trailing member's padding; never upload less
      // than the members need.
      for (const UniformMember& m : block.members) block.size = std::max(block.size, m.offset + m.size);
      const auto same_binding = std::ranges::find(result.uniform_blocks, block.binding, &UniformBlock::binding);
      if (same_binding == result.uniform_blocks.end()) {
        result.uniform_blocks.push_back(std::move(block));
        block_stage.push_back(module->stage);
        continue;
      }
      // A block both stages declare identically is one buffer; anything else sharing a
      // binding would make one stage read the other's bytes.
      if (same_layout(*same_binding, block)) continue;
      const Stage other = block_stage[size_t(same_binding - result.uniform_blocks.begin())];
      return std::unexpected(gl_error("uniform blocks " + describe(*same_binding, other) + " and " +
                                      describe(block, module->stage) + " both use binding " +
                                      std::to_string(block.binding) + ", and GL has one binding namespace for all stages")
                                 .in_file(module->source_file));
    }
    for (const SamplerBinding& sampler : module->reflection.samplers) {
      const auto same_unit = std::ranges::find(result.samplers, sampler.binding, &SamplerBinding::binding);
      if (same_unit == result.samplers.end()) {
        result.samplers.push_back(sampler);
        continue;
      }
      if (same_unit->name == sampler.name && same_unit->dimensions == sampler.dimensions) continue;
      return std::unexpected(gl_error("samplers '" + same_unit->name + "' (" + std::to_string(same_unit->dimensions) +
                                      "D) and '" + sampler.name + "' (" + std::to_string(sampler.dimensions) +
                                      "D) both use texture unit " + std::to_string(sampler.binding) +
                                      ", and GL has one unit namespace for all stages")
                                 .in_file(module->source_file));
    }
  }
  result.inputs = program.vertex_gl.reflection.inputs;
  return result;
}

namespace {

Result<void> check_cross_glsl_samplers(const GlProgramInterface& from_gl, const GlProgramInterface& reflected) {
  for (const SamplerBinding& gl_sampler : from_gl.samplers) {
    const auto match = std::ranges::find(reflected.samplers, gl_sampler.binding, &SamplerBinding::binding);
    if (match == reflected.samplers.end())
      return std::unexpected(gl_error("SPIRV-Cross GLSL reads sampler '" + gl_sampler.name + "' from texture unit " +
                                      std::to_string(gl_sampler.binding) +
                                      ", where the SPIR-V reflection has no sampler (layout(binding) lost?)"));
    if (match->dimensions != gl_sampler.dimensions)
      return std::unexpected(gl_error("SPIRV-Cross GLSL declares sampler '" + gl_sampler.name + "' at unit " +
                                      std::to_string(gl_sampler.binding) + " as " +
                                      std::to_string(gl_sampler.dimensions) + "D, the SPIR-V reflection says '" +
                                      match->name + "' " + std::to_string(match->dimensions) + "D"));
  }
  return {};
}

}  // namespace

Result<void> check_cross_glsl_layout(const GlProgramInterface& from_gl, const GlProgramInterface& reflected) {
  if (auto ok = check_cross_glsl_samplers(from_gl, reflected); !ok) return ok;
  for (const UniformBlock& gl_block : from_gl.uniform_blocks) {
    const auto match = std::ranges::find(reflected.uniform_blocks, gl_block.binding, &UniformBlock::binding);
    if (match == reflected.uniform_blocks.end())
      return std::unexpected(gl_error("SPIRV-Cross GLSL declares block '" + gl_block.name + "' at binding " +
                                      std::to_string(gl_block.binding) + ", where the SPIR-V reflection has no block"));
    for (const UniformMember& gl_member : gl_block.members) {
      const auto member = std::ranges::find(match->members, gl_member.name, &UniformMember::name);
      // Struct leaves ("s.f") have no reflected counterpart of their own; skip them.
      if (member == match->members.end()) continue;
      const auto differs = [&](const char* what, uint32_t gl_value, uint32_t reflected_value) -> Result<void> {
        if (gl_value == reflected_value) return {};
        return std::unexpected(gl_error("SPIRV-Cross GLSL lays out '" + gl_member.name + "' of block '" +
                                        match->name + "' with " + what + " " + std::to_string(gl_value) +
                                        ", the SPIR-V reflection says " + std::to_string(reflected_value)));
      };
      if (auto ok = differs("offset", gl_member.offset, member->offset); !ok) return ok;
      if (member->array_size > 0)
        if (auto ok = differs("array stride", gl_member.array_stride, member->array_stride); !ok) return ok;
      if (member->columns > 1 || member->vecsize > 1)
        if (gl_member.matrix_stride && member->matrix_stride)
          if (auto ok = differs("matrix stride", gl_member.matrix_stride, member->matrix_stride); !ok) return ok;
    }
  }
  return {};
}

}  // namespace shaderbed::gl
