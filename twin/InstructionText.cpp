#include "twin/InstructionText.h"

#include <spirv/unified1/spirv.hpp11>

#include <cmath>
#include <sstream>

#include "twin/OpcodeNames.gen.h"

namespace twin {

std::string number_text(double v) {
  if (std::isnan(v)) return "NaN";
  if (std::isinf(v)) return v > 0 ? "+Inf" : "-Inf";
  std::ostringstream out;
  out.precision(9);
  out << v;
  return out.str();
}

std::string values_text(const std::vector<double>& values) {
  if (values.size() == 1) return number_text(values[0]);
  std::string s = "(";
  for (size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + number_text(values[i]);
  return s + ")";
}

namespace {

std::string ext_name(uint32_t op) {
  for (const auto& entry : generated::glsl_std450_names)
    if (entry.opcode == op) return std::string("GLSL.std.450 ") + entry.name;
  return "GLSL.std.450 " + std::to_string(op);
}

}  // namespace

std::string operation_name(const Module& m, const Instruction& in) {
  if (spv::Op(in.op) == spv::Op::OpExtInst) {
    const auto operands = m.operands_of(in);
    return operands.size() > 1 ? ext_name(operands[1]) : opcode_name(in.op);
  }
  return opcode_name(in.op);
}

std::span<const uint32_t> value_operands(const Module& m, const Instruction& in) {
  auto operands = m.operands_of(in);
  if (spv::Op(in.op) == spv::Op::OpExtInst) return operands.size() >= 2 ? operands.subspan(2) : operands.subspan(0, 0);
  return operands;
}

ValueNames::ValueNames(const Module& m) : m_(m) {
  for (const Instruction& i : m.instructions)
    if (spv::Op(i.op) == spv::Op::OpLoad && i.operand_count > 0) loaded_from_[i.result] = m.operands_of(i)[0];
}

std::string ValueNames::operator()(uint32_t id) const {
  if (auto it = m_.names.find(id); it != m_.names.end()) return it->second;
  // An unnamed temporary loaded from a named variable goes by the variable's name.
  if (auto it = loaded_from_.find(id); it != loaded_from_.end())
    if (auto named = m_.names.find(it->second); named != m_.names.end()) return named->second;
  return m_.name_of(id);
}

const SourceLine& line_of(const Module& m, const Instruction& in) { return m.lines[in.line]; }

}  // namespace twin
