#include "twin/ValueNames.h"

#include <spirv/unified1/spirv.hpp11>

#include "twin/OpcodeNames.gen.h"

namespace twin {

ValueNames::ValueNames(const Module& module) : m_(module) {
  for (const Instruction& i : m_.instructions)
    if (spv::Op(i.op) == spv::Op::OpLoad) loaded_from_[i.result] = m_.operands_of(i)[0];
}

std::string ValueNames::operator()(uint32_t id) const {
  if (auto it = m_.names.find(id); it != m_.names.end()) return it->second;
  if (auto it = loaded_from_.find(id); it != loaded_from_.end())
    if (auto named = m_.names.find(it->second); named != m_.names.end()) return named->second;
  return m_.name_of(id);
}

std::string operation_name(const Module& module, const Instruction& instruction) {
  if (spv::Op(instruction.op) != spv::Op::OpExtInst) return opcode_name(instruction.op);
  const uint32_t op = module.operands_of(instruction)[1];
  for (const auto& entry : generated::glsl_std450_names)
    if (entry.opcode == op) return std::string("GLSL.std.450 ") + entry.name;
  return "GLSL.std.450 " + std::to_string(op);
}

std::span<const uint32_t> value_operands(const Module& module, const Instruction& instruction) {
  auto operands = module.operands_of(instruction);
  return spv::Op(instruction.op) == spv::Op::OpExtInst ? operands.subspan(2) : operands;
}

const SourceLine& line_of(const Module& module, const Instruction& instruction) {
  return module.lines[instruction.line];
}

}  // namespace twin
