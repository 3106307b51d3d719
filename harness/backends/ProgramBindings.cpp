#include "backends/ProgramBindings.h"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "backends/TextureShape.h"

namespace shaderbed {
namespace {

bool same_member(const UniformMember& a, const UniformMember& b) {
  return a.name == b.name && a.offset == b.offset && a.size == b.size && a.is_float == b.is_float &&
         a.vecsize == b.vecsize && a.columns == b.columns && a.matrix_stride == b.matrix_stride &&
         a.column_registers == b.column_registers && a.array_size == b.array_size && a.array_stride == b.array_stride;
}

bool same_block(const UniformBlock& a, const UniformBlock& b) {
  return a.name == b.name && a.size == b.size &&
         std::ranges::equal(a.members, b.members, [](const auto& x, const auto& y) { return same_member(x, y); });
}

std::string where(const UniformBlock& block) {
  return "uniform block '" + block.name + "' (set " + std::to_string(block.set) + ", binding " +
         std::to_string(block.binding) + ")";
}

// Adds the block (and member, unless the resolver already named it) to resolver errors,
// so "no value" becomes an error a user can act on whichever resolver produced it.
class BlockContextResolver final : public UniformResolver {
 public:
  explicit BlockContextResolver(const UniformResolver& inner) : inner_(inner) {}
  Result<std::vector<double>> value(const UniformBlock& block, const UniformMember& member) const override {
    auto v = inner_.value(block, member);
    if (v) return v;
    Error e = std::move(v.error());
    std::string context = where(block);
    if (e.message.find(member.name) == std::string::npos) context += ", member '" + member.name + "'";
    e.message = context + ": " + e.message;
    return std::unexpected(std::move(e));
  }

 private:
  const UniformResolver& inner_;
};

const char* kind_text(SamplerKind kind) {
  return kind == SamplerKind::combined ? "sampler" : kind == SamplerKind::image ? "texture" : "sampler state";
}

std::string where(const SamplerBinding& sampler) {
  return std::string(kind_text(sampler.kind)) + " '" + sampler.name + "' (set " + std::to_string(sampler.set) +
         ", binding " + std::to_string(sampler.binding) + ")";
}

// No stage: the backend that binds says it is its own (Error::in_stage).
Error bindings_error(std::string message) { return Error{.message = std::move(message)}; }

}  // namespace

Result<std::vector<UniformBlock>> program_uniform_blocks(const CompiledProgram& program) {
  std::map<std::pair<uint32_t, uint32_t>, UniformBlock> by_binding;
  for (const ShaderModule* module : {&program.vertex, &program.fragment}) {
    for (const UniformBlock& block : module->reflection.uniform_blocks) {
      auto [it, inserted] = by_binding.try_emplace({block.set, block.binding}, block);
      if (!inserted && !same_block(it->second, block))
        return std::unexpected(bindings_error("the vertex and fragment shaders declare different uniform blocks at set " +
                                             std::to_string(block.set) + ", binding " + std::to_string(block.binding) +
                                             " ('" + it->second.name + "' and '" + block.name + "')"));
    }
  }
  std::vector<UniformBlock> blocks;
  for (auto& [key, block] : by_binding) blocks.push_back(std::move(block));
  return blocks;
}

Result<std::vector<PackedBlock>> pack_uniform_blocks(const std::vector<UniformBlock>& blocks,
                                                     const UniformResolver& resolver) {
  const BlockContextResolver with_context(resolver);
  std::vector<PackedBlock> packed;
  for (const UniformBlock& block : blocks) {
    auto bytes = pack_uniform_block(block, with_context);
    if (!bytes) return std::unexpected(std::move(bytes.error()));
    packed.push_back({block, std::move(*bytes)});
  }
  return packed;
}

Result<std::vector<SamplerBinding>> program_samplers(const CompiledProgram& program,
                                                     const std::vector<UniformBlock>& blocks) {
  std::map<std::pair<uint32_t, uint32_t>, SamplerBinding> by_binding;
  for (const ShaderModule* module : {&program.vertex, &program.fragment}) {
    for (const SamplerBinding& sampler : module->reflection.samplers) {
      const auto block = std::ranges::find_if(blocks, [&](const UniformBlock& b) {
        return b.set == sampler.set && b.binding == sampler.binding;
      });
      if (block != blocks.end())
        return std::unexpected(bindings_error(where(sampler) + " and uniform block '" + block->name +
                                             "' share one descriptor binding")
                                   .in_file(module->source_file));
      auto [it, inserted] = by_binding.try_emplace({sampler.set, sampler.binding}, sampler);
      if (!inserted && (it->second.name != sampler.name || it->second.kind != sampler.kind ||
                        it->second.dimensions != sampler.dimensions || it->second.cube != sampler.cube))
        return std::unexpected(bindings_error("the vertex and fragment shaders declare different samplers at set " +
                                             std::to_string(sampler.set) + ", binding " +
                                             std::to_string(sampler.binding) + " (" + where(it->second) + " " +
                                             sampler_type_text(it->second) + " and " + where(sampler) + " " +
                                             sampler_type_text(sampler) + ")"));
      if (!inserted)
        for (const std::string& p : sampler.paired)
          if (std::ranges::find(it->second.paired, p) == it->second.paired.end()) it->second.paired.push_back(p);
    }
  }
  std::vector<SamplerBinding> samplers;
  for (auto& [key, sampler] : by_binding) samplers.push_back(std::move(sampler));
  return samplers;
}

}  // namespace shaderbed
