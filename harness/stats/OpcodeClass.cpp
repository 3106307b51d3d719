#include "stats/OpcodeClass.h"

#include <algorithm>
#include <array>

#include "stats/OpcodeClasses.gen.h"   // generated into the build tree

namespace shaderbed::stats {
namespace {

const generated::OpcodeRow* find_row(uint32_t opcode) {
  const auto& rows = generated::kOpcodes;
  auto it = std::lower_bound(std::begin(rows), std::end(rows), opcode,
                             [](const generated::OpcodeRow& r, uint32_t op) { return r.opcode < op; });
  return it != std::end(rows) && it->opcode == opcode ? &*it : nullptr;
}

}  // namespace

const char* to_string(InstructionClass c) {
  switch (c) {
    case InstructionClass::arithmetic: return "arithmetic";
    case InstructionClass::extended: return "extended";
    case InstructionClass::texture: return "texture";
    case InstructionClass::control: return "control";
    case InstructionClass::memory: return "memory";
    case InstructionClass::conversion: return "conversion";
    case InstructionClass::other: return "other";
    case InstructionClass::none: return "none";
  }
  return "?";
}

InstructionClass opcode_class(uint32_t opcode) {
  const auto* row = find_row(opcode);
  return row ? row->cls : InstructionClass::other;
}

std::string opcode_name(uint32_t opcode) {
  const auto* row = find_row(opcode);
  return row ? row->name : "";
}

std::string glsl_std_450_name(uint32_t number) {
  for (const auto& r : generated::kGlslStd450)
    if (r.number == number) return r.name;
  return "";
}

const char* grammar_version() { return generated::kGrammarVersion; }

}  // namespace shaderbed::stats
