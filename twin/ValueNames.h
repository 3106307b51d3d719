#pragma once
// What messages call a module's values and instructions: a value by its OpName, an unnamed
// temporary loaded from a named variable by the variable's name, else %id; an instruction
// by its opcode or GLSL.std.450 name; and its value operands (an extended instruction's
// set and number left out).
#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>

#include "twin/Module.h"

namespace twin {

class ValueNames {
 public:
  explicit ValueNames(const Module& module);
  std::string operator()(uint32_t id) const;

 private:
  const Module& m_;
  std::unordered_map<uint32_t, uint32_t> loaded_from_;   // OpLoad result -> its pointer
};

// "OpFDiv", "GLSL.std.450 Pow".
std::string operation_name(const Module& module, const Instruction& instruction);
// The instruction's operand words that may be ids of values (for OpExtInst, after the set
// and the instruction number).
std::span<const uint32_t> value_operands(const Module& module, const Instruction& instruction);
// The source line an instruction carries ({"", 0} when none).
const SourceLine& line_of(const Module& module, const Instruction& instruction);

}  // namespace twin
