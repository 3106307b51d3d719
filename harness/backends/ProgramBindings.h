#pragma once
// What a program binds, independent of any device: both stages' uniform blocks merged by
// (set, binding) and packed from the UniformResolver, and both stages' samplers merged
// the same way. Every backend (Vulkan, the twin) binds from these.
#include <cstddef>
#include <vector>

#include "backends/UniformPacking.h"
#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed {

// The union of both stages' uniform blocks, sorted by (set, binding). A block declared
// at the same set/binding by both stages must be identical there. Samplers are left to
// program_samplers.
Result<std::vector<UniformBlock>> program_uniform_blocks(const CompiledProgram& program);

struct PackedBlock {
  UniformBlock block;
  std::vector<std::byte> bytes;
};

// Every member of every block resolved and packed, before anything is drawn, so a
// missing binding fails fast. Errors name the block (and the member).
Result<std::vector<PackedBlock>> pack_uniform_blocks(const std::vector<UniformBlock>& blocks,
                                                     const UniformResolver& resolver);

// The union of both stages' samplers, sorted by (set, binding). A sampler both stages
// declare at one set/binding must agree on name, kind and type; a sampler at the
// set/binding of a uniform block is an error (one descriptor cannot be both).
Result<std::vector<SamplerBinding>> program_samplers(const CompiledProgram& program,
                                                     const std::vector<UniformBlock>& blocks);

}  // namespace shaderbed
