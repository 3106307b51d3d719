#pragma once
// Which values each value of a module is computed from, statically: an instruction's
// operands, and through memory every value stored into the variables a load reads (a
// function's parameters and results included). Over-approximates a run's data flow, which
// is what the divergence search needs: whether a value can reach the stage's outputs, and
// what its inputs are.
#include <cstdint>
#include <vector>

#include "twin/Module.h"

namespace twin {

struct DataFlow {
  enum class Kind : uint8_t {
    computed,   // arithmetic, calls to GLSL.std.450, sampling, ...
    copy,       // a load of a function's own variable, a call's result, OpCopyObject: what was stored
    read,       // a load of an input, uniform or other resource: where values enter the stage
  };
  std::vector<int32_t> defining;                // by id: the instruction that computes it, -1 none
  std::vector<Kind> kind;                       // by instruction
  std::vector<std::vector<uint32_t>> inputs;    // by instruction: the instructions it reads
  std::vector<uint8_t> output;                  // by instruction: its value is stored to an output
  std::vector<uint8_t> reaches_output;          // by instruction: an output depends on it
  std::vector<uint32_t> read_variable;          // by instruction: for `read`, the variable read, else 0
};

DataFlow data_flow(const Module& module);

// Whether `id` names a value (not a type, literal or pointer) in `module`.
bool is_value(const Module& module, const DataFlow& flow, uint32_t id);

}  // namespace twin
