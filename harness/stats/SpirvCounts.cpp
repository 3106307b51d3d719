#include "stats/SpirvCounts.h"

#include <spirv-tools/libspirv.h>
#include <spirv/unified1/spirv.hpp11>

#include "stats/OpcodeClass.h"

namespace shaderbed::stats {
namespace {

struct ParseState {
  ClassCounts counts;
  bool in_function = false;
};

spv_result_t on_instruction(void* user, const spv_parsed_instruction_t* inst) {
  auto& s = *static_cast<ParseState*>(user);
  const auto opcode = spv::Op(inst->opcode);
  if (opcode == spv::Op::OpFunction) {
    s.in_function = true;
    return SPV_SUCCESS;
  }
  if (opcode == spv::Op::OpFunctionEnd) {
    s.in_function = false;
    return SPV_SUCCESS;
  }
  if (!s.in_function) return SPV_SUCCESS;
  ClassCounts& c = s.counts;
  switch (opcode_class(inst->opcode)) {
    case InstructionClass::none: return SPV_SUCCESS;
    case InstructionClass::arithmetic: ++c.arithmetic; break;
    case InstructionClass::texture: ++c.texture; break;
    case InstructionClass::control: ++c.control; break;
    case InstructionClass::memory: ++c.memory; break;
    case InstructionClass::conversion: ++c.conversion; break;
    case InstructionClass::other: ++c.other; break;
    case InstructionClass::extended:
      if (opcode == spv::Op::OpExtInst && inst->ext_inst_type == SPV_EXT_INST_TYPE_GLSL_STD_450 &&
          inst->num_words > 4) {
        ++c.extended;
        std::string name = glsl_std_450_name(inst->words[4]);
        ++c.extended_calls[name.empty() ? "GLSL.std.450#" + std::to_string(inst->words[4]) : name];
      } else {
        ++c.other;   // other instruction sets (NonSemantic debug info...) are not GLSL calls
      }
      break;
  }
  ++c.total;
  return SPV_SUCCESS;
}

}  // namespace

Result<ClassCounts> count_spirv(const std::vector<uint32_t>& spirv) {
  spv_context context = spvContextCreate(SPV_ENV_UNIVERSAL_1_6);
  ParseState state;
  spv_diagnostic diagnostic = nullptr;
  spv_result_t r =
      spvBinaryParse(context, &state, spirv.data(), spirv.size(), nullptr, on_instruction, &diagnostic);
  std::string message = diagnostic && diagnostic->error ? diagnostic->error : "spvBinaryParse failed";
  spvDiagnosticDestroy(diagnostic);
  spvContextDestroy(context);
  if (r != SPV_SUCCESS) return fail(ErrorStage::stats, message);
  return state.counts;
}

}  // namespace shaderbed::stats
