#include "twin/InstructionText.h"

#include <spirv/unified1/spirv.hpp11>

#include <algorithm>
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
  switch (spv::Op(in.op)) {
    case spv::Op::OpExtInst: return operands.size() >= 2 ? operands.subspan(2) : operands.subspan(0, 0);
    // Literal indices and components after the composites, which could read as ids.
    case spv::Op::OpCompositeExtract: return operands.first(std::min<size_t>(operands.size(), 1));
    case spv::Op::OpCompositeInsert:
    case spv::Op::OpVectorShuffle: return operands.first(std::min<size_t>(operands.size(), 2));
    default: return operands;
  }
}

bool float_typed(const Module& m, uint32_t type_id) {
  const Type* t = &m.types[type_id];
  while (t->kind == Type::Kind::vector || t->kind == Type::Kind::matrix || t->kind == Type::Kind::array)
    t = &m.types[t->element];
  return t->kind == Type::Kind::floating;
}

ValueNames::ValueNames(const Module& m) : m_(m) {
  for (const Instruction& i : m.instructions) {
    const spv::Op op = spv::Op(i.op);
    if (op == spv::Op::OpLoad && i.operand_count > 0) loaded_from_[i.result] = m.operands_of(i)[0];
    if ((op == spv::Op::OpAccessChain || op == spv::Op::OpInBoundsAccessChain) && i.operand_count > 0) chains_[i.result] = &i;
    if (op == spv::Op::OpStore && i.operand_count > 1 && m.names.contains(m.operands_of(i)[0]))
      stored_into_.try_emplace(m.operands_of(i)[1], m.operands_of(i)[0]);
  }
}

// A variable's name, or a member's through an access chain with constant indices: the
// variable's name and the members' ("input.Normal"); an anonymous block's members alone.
std::string ValueNames::pointer_name(uint32_t pointer) const {
  if (auto named = m_.names.find(pointer); named != m_.names.end()) return named->second;
  auto chain = chains_.find(pointer);
  if (chain == chains_.end()) return "";
  const auto ops = m_.operands_of(*chain->second);
  std::string name = pointer_name(ops[0]);
  uint32_t type = m_.types[m_.type_of[ops[0]]].element;   // the pointee
  for (size_t k = 1; k < ops.size(); ++k) {
    const Type& t = m_.types[type];
    const bool constant = ops[k] < m_.bound && m_.is_constant[ops[k]] && !m_.constants[ops[k]].empty();
    if (t.kind != Type::Kind::structure || !constant) {
      if (name.empty()) return "";
      name += constant ? "[" + std::to_string(int64_t(m_.constants[ops[k]][0])) + "]" : "[...]";
      type = t.element;
      continue;
    }
    const auto member = uint32_t(m_.constants[ops[k]][0]);
    auto member_name = m_.member_names.find({type, member});
    if (member_name == m_.member_names.end() || member >= t.members.size()) return "";
    name = name.empty() ? member_name->second : name + "." + member_name->second;
    type = t.members[member];
  }
  return name;
}

std::string ValueNames::operator()(uint32_t id) const {
  if (auto it = m_.names.find(id); it != m_.names.end()) return it->second;
  if (auto it = loaded_from_.find(id); it != loaded_from_.end())
    if (std::string name = pointer_name(it->second); !name.empty()) return name;
  if (std::string name = stored_as(id); !name.empty()) return name;
  return m_.name_of(id);
}

std::string ValueNames::stored_as(uint32_t id) const {
  auto it = stored_into_.find(id);
  return it == stored_into_.end() ? "" : m_.names.at(it->second);
}

const SourceLine& line_of(const Module& m, const Instruction& in) { return m.lines[in.line]; }

}  // namespace twin
