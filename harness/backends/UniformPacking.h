#pragma once
// Fills a uniform block's bytes from reflection: every member the shader declares is
// asked for by name (or by its D3D register, offset / 16) and written at its offset.
// A member nobody supplies is an error naming it: nothing is silently left zero.
#include <cstddef>
#include <vector>

#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed {

class UniformResolver {
 public:
  virtual ~UniformResolver() = default;
  // Value for one member, in double until a backend stores it: scalars 1, vectors up to 4
  // (extra components are ignored), matrices 16 column-major values of M in "clip = M * v".
  virtual Result<std::vector<double>> value(const UniformBlock& block, const UniformMember& member) const = 0;
};

Result<std::vector<std::byte>> pack_uniform_block(const UniformBlock& block, const UniformResolver& resolver);

// The same values before they are stored as 32-bit words, one double per word of the block
// (integers as their value): what a backend that computes in double reads (the twin).
Result<std::vector<double>> uniform_block_values(const UniformBlock& block, const UniformResolver& resolver);

}  // namespace shaderbed
