#pragma once
// How an instruction and its values read in a message: numbers, an instruction's operation
// ("OpFSub", "GLSL.std.450 Pow") and its value operands, and the names of values (OpName,
// or the variable an unnamed load read). Shared by the twin's explanations (ValueOrigin,
// SignificanceLoss).
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "twin/Module.h"

namespace twin {

// "0.5", "NaN", "+Inf" (9 significant digits).
std::string number_text(double v);
// One value as number_text, several as "(a, b, c)".
std::string values_text(const std::vector<double>& values);

// The operation an instruction performs, for messages: "OpFDiv", "GLSL.std.450 Sqrt".
std::string operation_name(const Module& m, const Instruction& in);
// The instruction's operand words that may be values: an OpExtInst's set and opcode, and
// the literal indices of a composite extract or insert or a shuffle's components, left out.
std::span<const uint32_t> value_operands(const Module& m, const Instruction& in);
// A float scalar, vector, matrix or array of them.
bool float_typed(const Module& m, uint32_t type_id);

// The source line an instruction carries ({"", 0} when none).
const SourceLine& line_of(const Module& m, const Instruction& in);

// Names of values: OpName; else what an unnamed load read (a variable, or a member of one
// through an access chain: "input.Normal", "Base"); else the named variable the value is
// stored into; else %id.
class ValueNames {
 public:
  explicit ValueNames(const Module& m);
  std::string operator()(uint32_t id) const;
  // The named variable `id` is (first) stored into; "" when none.
  std::string stored_as(uint32_t id) const;

 private:
  std::string pointer_name(uint32_t pointer) const;
  const Module& m_;
  std::map<uint32_t, uint32_t> loaded_from_;
  std::map<uint32_t, const Instruction*> chains_;   // access chain result -> its instruction
  std::map<uint32_t, uint32_t> stored_into_;        // value -> the first variable it is stored into
};

}  // namespace twin
