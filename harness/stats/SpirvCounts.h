#pragma once
// Instruction counts of one SPIR-V module by class, from parsing it with spvBinaryParse.
// Only instructions inside function bodies count; what counts as what is the generated
// grammar table (OpcodeClass.h, gen_opcode_classes.py).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/Error.h"

namespace shaderbed::stats {

struct ClassCounts {
  int total = 0;   // sum of the seven classes below
  int arithmetic = 0, extended = 0, texture = 0, control = 0, memory = 0, conversion = 0, other = 0;
  // The extended (GLSL.std.450) calls by name: {"Normalize": 2, "Pow": 1}.
  std::map<std::string, int> extended_calls;
  bool operator==(const ClassCounts&) const = default;
};

Result<ClassCounts> count_spirv(const std::vector<uint32_t>& spirv);

}  // namespace shaderbed::stats
