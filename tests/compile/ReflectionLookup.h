#pragma once
// Finding what reflection reports, by name, for the compile tests.
#include <string>

#include "compile/ShaderModule.h"

namespace shaderbed::test {

// The uniform member called `name` in any uniform block; nullptr when there is none.
inline const UniformMember* find_member(const Reflection& r, const std::string& name) {
  for (const UniformBlock& b : r.uniform_blocks)
    for (const UniformMember& m : b.members)
      if (m.name == name) return &m;
  return nullptr;
}

}  // namespace shaderbed::test
