#pragma once
// SPIR-V instruction classes for `shaderbed stats`. The opcode -> class table is generated
// at build time from the SPIR-V grammar JSON (gen_opcode_classes.py), not typed by hand.
#include <cstdint>
#include <string>

namespace shaderbed::stats {

// "none": not an instruction that does work (declarations, block markers, debug info).
enum class InstructionClass { arithmetic, extended, texture, control, memory, conversion, other, none };

const char* to_string(InstructionClass);

// The class of a core opcode; unknown opcodes (newer than the grammar) count as "other".
InstructionClass opcode_class(uint32_t opcode);

// "OpFMul"; "" for an opcode the grammar does not know.
std::string opcode_name(uint32_t opcode);

// GLSL.std.450 extended instruction name ("Pow", "Normalize"...); "" when unknown.
std::string glsl_std_450_name(uint32_t number);

// major.minor.revision of the grammar the table was generated from.
const char* grammar_version();

}  // namespace shaderbed::stats
