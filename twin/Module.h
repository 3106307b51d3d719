#pragma once
// A SPIR-V module decoded once into what the twin executes: types with their flattened
// size, constants as doubles, decorations by id, functions as blocks of instructions with
// their structured merges, and the source line of every instruction (OpLine). Decoding
// goes through SPIRV-Tools (spvBinaryParse) after spirv-val accepts the module, so the
// executor may assume a well-formed, structured module.
#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "twin/Error.h"

namespace twin {

// Every value is a sequence of scalar slots: a vector's components, a matrix's columns one
// after the other, an array's elements, a struct's members. Opaque handles take one slot.
struct Type {
  enum class Kind : uint8_t {
    none, void_, boolean, integer, floating, vector, matrix, array, runtime_array, structure, pointer,
    function, image, sampler, sampled_image,
  };
  Kind kind = Kind::none;
  uint32_t width = 32;
  bool is_signed = false;
  uint32_t element = 0;    // vector/matrix/array element, pointer pointee, sampled image's image
  uint32_t count = 0;      // vector components, matrix columns, array length
  uint32_t storage = 0;    // pointer: spv::StorageClass
  uint32_t slots = 0;      // flattened scalar count
  std::vector<uint32_t> members;        // struct member types
  std::vector<uint32_t> member_slots;   // where each member starts, in slots
  // Memory layout (uniform and push-constant blocks): ArrayStride; per member Offset,
  // MatrixStride and RowMajor; built-in decorations of gl_PerVertex's members; an
  // interface block member's own interpolation (glslang puts `flat` there, not on the block).
  uint32_t array_stride = 0;
  std::vector<uint32_t> member_offset, member_matrix_stride;
  std::vector<uint8_t> member_row_major, member_flat, member_noperspective;
  std::vector<int> member_builtin, member_location;
  // Image: Dim, Arrayed, MS, Sampled.
  uint32_t dim = 0;
  bool arrayed = false;
  bool is_float() const { return kind == Kind::floating; }
};

struct Decoration {
  int builtin = -1, location = -1, component = 0, set = -1, binding = -1, index = 0;
  bool flat = false, noperspective = false, relaxed = false, row_major = false;
  uint32_t matrix_stride = 0;
};

struct Instruction {
  uint16_t op = 0;
  uint16_t operand_count = 0;
  uint32_t result_type = 0;
  uint32_t result = 0;
  uint32_t first_operand = 0;   // into Module::operands (the words after result type and id)
  uint32_t line = 0;            // into Module::lines; 0 = no line
};

struct Block {
  uint32_t label = 0;
  uint32_t first = 0, last = 0;   // instructions [first, last]; last is the terminator
  uint32_t merge = 0;             // OpSelectionMerge / OpLoopMerge target, 0 = none
  uint32_t continue_target = 0;   // loops only
  uint64_t cost = 0;              // what one pass costs, in values read and written (Executor's work limit)
};

struct Function {
  uint32_t id = 0;
  uint32_t result_type = 0;
  std::vector<uint32_t> parameters;
  std::vector<Block> blocks;                    // blocks[0] is the entry
  std::unordered_map<uint32_t, uint32_t> block_of;   // label -> index in blocks
};

struct SourceLine {
  std::string file;
  int line = 0;
};

struct Module {
  uint32_t bound = 0;
  uint32_t execution_model = 0;        // spv::ExecutionModel of the entry point
  uint32_t entry_function = 0;
  std::string entry_name;
  std::vector<uint32_t> interface;     // the entry point's Input/Output variables
  bool origin_lower_left = false;
  std::vector<Type> types;             // by id
  std::vector<Decoration> decorations; // by id
  std::vector<uint8_t> is_constant;    // by id: constants, spec constants' defaults, undef
  std::vector<std::vector<double>> constants;
  std::vector<uint32_t> type_of;       // by id: result type of every value
  std::vector<uint32_t> variables;     // module-scope OpVariable ids
  std::vector<uint32_t> variable_initializer;   // by id, 0 = none
  std::unordered_map<uint32_t, Function> functions;
  std::vector<Instruction> instructions;
  std::vector<uint32_t> operands;
  std::vector<SourceLine> lines;       // lines[0] is "no line"
  std::vector<uint8_t> glsl_std450;    // by id: the id is the GLSL.std.450 import
  std::vector<uint8_t> non_semantic;   // by id: an import whose instructions do nothing
  std::map<uint32_t, std::string> names;   // OpName
  std::map<std::pair<uint32_t, uint32_t>, std::string> member_names;   // (struct type, member) -> OpMemberName
  std::map<std::string, std::string> sources;   // file -> source text (OpSource), when present

  std::span<const uint32_t> operands_of(const Instruction& i) const {
    return {operands.data() + i.first_operand, i.operand_count};
  }
  const Type& type(uint32_t id) const { return types[id]; }
  std::string name_of(uint32_t id) const;
};

// spirv-val (Vulkan 1.0 rules, as the compile stage targets) then decode. `entry_point`
// names the OpEntryPoint to run.
TwinResult<std::shared_ptr<const Module>> load_module(std::span<const uint32_t> spirv, const std::string& entry_point);

// "OpFAdd" for an opcode number (from SPIRV-Tools' grammar), for messages.
std::string opcode_name(uint32_t op);

}  // namespace twin
