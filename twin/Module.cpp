#include "twin/Module.h"

#include <spirv-tools/libspirv.h>
#include <spirv/unified1/spirv.hpp11>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "twin/OpcodeNames.gen.h"

namespace twin {
namespace {

using spv::Op;

struct RawInstruction {
  uint16_t op;
  std::vector<uint32_t> words;   // operands after the opcode word
  std::vector<uint16_t> ids;     // which of `words` are ids
};

bool is_id(spv_operand_type_t type) {
  return type == SPV_OPERAND_TYPE_ID || type == SPV_OPERAND_TYPE_TYPE_ID || type == SPV_OPERAND_TYPE_RESULT_ID ||
         type == SPV_OPERAND_TYPE_MEMORY_SEMANTICS_ID || type == SPV_OPERAND_TYPE_SCOPE_ID;
}

// Renumbers the ids densely, in their order, and returns the new bound. Valid SPIR-V may use
// any ids below a bound of up to 2^22, and every table by id (the module's and each
// executor's) would then hold millions of entries: 2 GB and 15 s to draw a seed whose
// header alone was changed.
uint32_t compact_ids(std::vector<RawInstruction>& raw) {
  std::vector<uint32_t> used;
  for (const RawInstruction& r : raw)
    for (uint16_t i : r.ids) used.push_back(r.words[i]);
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  for (RawInstruction& r : raw)
    for (uint16_t i : r.ids)
      r.words[i] = uint32_t(std::lower_bound(used.begin(), used.end(), r.words[i]) - used.begin()) + 1;
  return uint32_t(used.size()) + 1;
}

std::string literal_string(std::span<const uint32_t> words) {
  std::string s;
  for (uint32_t w : words)
    for (int b = 0; b < 4; ++b) {
      const char c = char((w >> (8 * b)) & 0xff);
      if (c == 0) return s;
      s.push_back(c);
    }
  return s;
}

// Words a literal string occupies (with its terminating zero).
size_t string_words(std::span<const uint32_t> words) {
  for (size_t i = 0; i < words.size(); ++i)
    for (int b = 0; b < 4; ++b)
      if (((words[i] >> (8 * b)) & 0xff) == 0) return i + 1;
  return words.size();
}

bool has_result_type(Op op) {
  bool result = false, type = false;
  spv::HasResultAndType(op, &result, &type);
  return type;
}
bool has_result(Op op) {
  bool result = false, type = false;
  spv::HasResultAndType(op, &result, &type);
  return result;
}

// What one invocation may hold (registers and variables) and what the module's constants
// may hold, counted in values (a scalar, a handle, a struct: one each). The executor keeps
// every invocation's values for a whole batch, and loops over a type's elements: a valid
// module can declare arrays of 2^32 elements, which would exhaust memory or never finish.
constexpr uint64_t max_invocation_values = uint64_t{1} << 18;
constexpr uint64_t max_constant_values = uint64_t{1} << 20;
constexpr uint64_t saturated = uint64_t{1} << 40;   // beyond every limit, far from overflow

uint64_t times(uint64_t a, uint64_t b) { return a && b > saturated / a ? saturated : std::min(a * b, saturated); }

class Decoder {
 public:
  Decoder(Module& m) : m_(m), elements_(m.bound, 0) {}

  TwinResult<void> decode(const std::vector<RawInstruction>& raw, const std::string& entry_point) {
    m_.lines.push_back({});
    std::map<uint32_t, std::string> strings;
    uint32_t current_line = 0;
    Function* function = nullptr;
    Block* block = nullptr;
    for (const RawInstruction& r : raw) {
      const Op op = Op(r.op);
      const std::span<const uint32_t> w(r.words);
      switch (op) {
        case Op::OpString: strings[w[0]] = literal_string(w.subspan(1)); continue;
        case Op::OpSource:
          if (w.size() > 3) sources_[w[2]] += literal_string(w.subspan(3));
          last_source_file_ = w.size() > 2 ? w[2] : 0;
          continue;
        case Op::OpSourceContinued:
          if (last_source_file_) sources_[last_source_file_] += literal_string(w);
          continue;
        case Op::OpName: m_.names[w[0]] = literal_string(w.subspan(1)); continue;
        case Op::OpMemberName: m_.member_names[{w[0], w[1]}] = literal_string(w.subspan(2)); continue;
        case Op::OpLine: {
          m_.lines.push_back({strings.count(w[0]) ? strings[w[0]] : "", int(w[1])});
          current_line = uint32_t(m_.lines.size() - 1);
          continue;
        }
        case Op::OpNoLine: current_line = 0; continue;
        case Op::OpExtInstImport: {
          const std::string name = literal_string(w.subspan(1));
          if (name == "GLSL.std.450") m_.glsl_std450[w[0]] = 1;
          else if (name.rfind("NonSemantic.", 0) == 0) m_.non_semantic[w[0]] = 1;
          continue;
        }
        case Op::OpEntryPoint: {
          const std::string name = literal_string(w.subspan(2));
          if (name == entry_point && m_.entry_function == 0) {
            m_.execution_model = w[0];
            m_.entry_function = w[1];
            m_.entry_name = name;
            const size_t first = 2 + string_words(w.subspan(2));
            m_.interface.assign(w.begin() + std::ptrdiff_t(first), w.end());
          }
          continue;
        }
        case Op::OpExecutionMode:
          if (spv::ExecutionMode(w[1]) == spv::ExecutionMode::OriginLowerLeft) origin_lower_left_.push_back(w[0]);
          continue;
        case Op::OpDecorate: decorate(m_.decorations[w[0]], spv::Decoration(w[1]), w.subspan(2)); continue;
        case Op::OpMemberDecorate: member_decorations_.push_back(r); continue;
        case Op::OpFunction: {
          function = &m_.functions[w[1]];
          function->id = w[1];
          function->result_type = w[0];
          continue;
        }
        case Op::OpFunctionParameter:
          function->parameters.push_back(w[1]);
          m_.type_of[w[1]] = w[0];
          continue;
        case Op::OpFunctionEnd: function = nullptr; block = nullptr; continue;
        case Op::OpLabel:
          function->block_of[w[0]] = uint32_t(function->blocks.size());
          function->blocks.push_back({.label = w[0], .first = uint32_t(m_.instructions.size())});
          block = &function->blocks.back();
          continue;
        case Op::OpSelectionMerge: block->merge = w[0]; continue;
        case Op::OpLoopMerge:
          block->merge = w[0];
          block->continue_target = w[1];
          continue;
        default: break;
      }
      if (!function) {
        if (auto ok = global(op, w); !ok) return ok;
        continue;
      }
      Instruction instruction{.op = r.op, .line = current_line};
      size_t first = 0;
      if (has_result_type(op)) instruction.result_type = w[first++];
      if (has_result(op)) instruction.result = w[first++];
      std::vector<uint32_t>& ids = operand_ids_.emplace_back();
      for (uint16_t i : r.ids)
        if (i >= first) ids.push_back(w[i]);
      if (instruction.result && instruction.result_type) m_.type_of[instruction.result] = instruction.result_type;
      instruction.first_operand = uint32_t(m_.operands.size());
      instruction.operand_count = uint16_t(w.size() - first);
      m_.operands.insert(m_.operands.end(), w.begin() + std::ptrdiff_t(first), w.end());
      m_.instructions.push_back(instruction);
      if (block) block->last = uint32_t(m_.instructions.size() - 1);
    }
    for (const RawInstruction& r : member_decorations_) member_decorate(r.words);
    for (uint32_t f : origin_lower_left_)
      if (f == m_.entry_function) m_.origin_lower_left = true;
    for (auto& [file_id, text] : sources_)
      if (strings.count(file_id)) m_.sources[strings[file_id]] = text;
    if (m_.entry_function == 0)
      return std::unexpected(TwinError{.message = "the module has no entry point named '" + entry_point + "'"});
    return check_limits();
  }

 private:
  void decorate(Decoration& d, spv::Decoration kind, std::span<const uint32_t> v) {
    switch (kind) {
      case spv::Decoration::BuiltIn: d.builtin = int(v[0]); break;
      case spv::Decoration::Location: d.location = int(v[0]); break;
      case spv::Decoration::Component: d.component = int(v[0]); break;
      case spv::Decoration::DescriptorSet: d.set = int(v[0]); break;
      case spv::Decoration::Binding: d.binding = int(v[0]); break;
      case spv::Decoration::Index: d.index = int(v[0]); break;
      case spv::Decoration::Flat: d.flat = true; break;
      case spv::Decoration::NoPerspective: d.noperspective = true; break;
      case spv::Decoration::RelaxedPrecision: d.relaxed = true; break;
      case spv::Decoration::RowMajor: d.row_major = true; break;
      case spv::Decoration::MatrixStride: d.matrix_stride = v[0]; break;
      default: break;
    }
  }

  void member_decorate(const std::vector<uint32_t>& w) {
    Type& t = m_.types[w[0]];
    const uint32_t member = w[1];
    if (member >= t.members.size()) return;
    const std::span<const uint32_t> v(w.data() + 3, w.size() - 3);
    switch (spv::Decoration(w[2])) {
      case spv::Decoration::Offset: t.member_offset[member] = v[0]; break;
      case spv::Decoration::MatrixStride: t.member_matrix_stride[member] = v[0]; break;
      case spv::Decoration::RowMajor: t.member_row_major[member] = 1; break;
      case spv::Decoration::BuiltIn: t.member_builtin[member] = int(v[0]); break;
      case spv::Decoration::Location: t.member_location[member] = int(v[0]); break;
      case spv::Decoration::Flat: t.member_flat[member] = 1; break;
      case spv::Decoration::NoPerspective: t.member_noperspective[member] = 1; break;
      default: break;
    }
  }

  // Slot counts, once every type is known (types are declared before use), and element
  // counts for the limits. Slots saturate rather than wrap: a type too large to hold is
  // refused where a value or a variable of it would be held (check_limits, charge_constant).
  void layout(uint32_t id) {
    Type& t = m_.types[id];
    using K = Type::Kind;
    auto slots = [](uint64_t n) { return uint32_t(std::min<uint64_t>(n, std::numeric_limits<uint32_t>::max())); };
    switch (t.kind) {
      case K::boolean: case K::integer: case K::floating: case K::image: case K::sampler: case K::sampled_image:
      case K::pointer:
        t.slots = 1;
        elements_[id] = 1;
        break;
      case K::runtime_array: elements_[id] = 1; break;
      case K::vector: case K::matrix: case K::array:
        t.slots = slots(uint64_t(t.count) * m_.types[t.element].slots);
        elements_[id] = times(t.count, elements_[t.element]);
        break;
      case K::structure: {
        uint64_t total = 0, elements = 1;
        t.member_slots.clear();
        for (uint32_t member : t.members) {
          t.member_slots.push_back(slots(total));
          total += m_.types[member].slots;
          elements = std::min(elements + elements_[member], saturated);
        }
        t.slots = slots(total);
        elements_[id] = elements;
        break;
      }
      default: break;
    }
  }

  // Values of type `type_id`, or of what it points to.
  uint64_t elements_of(uint32_t type_id) const {
    const Type& t = m_.types[type_id];
    return t.kind == Type::Kind::pointer ? elements_[t.element] : elements_[type_id];
  }

  // An array length: beyond uint32 it is saturated (the array is then refused where held).
  uint64_t constant_value(uint32_t id) const {
    if (!m_.is_constant[id] || m_.constants[id].empty()) return 0;
    const double v = m_.constants[id][0];
    return v >= 0 && v <= 4294967295.0 ? uint64_t(v) : v > 0 ? 4294967295u : 0;
  }

  TwinResult<void> charge_constant(uint32_t type_id) {
    constant_values_ = std::min(constant_values_ + elements_[type_id], saturated);
    if (constant_values_ <= max_constant_values) return {};
    return std::unexpected(TwinError{.message = "the module's constants hold more than " +
                                                std::to_string(max_constant_values) + " values"});
  }

  // What an instruction costs the executor: one per operand (a switch compares each lane
  // with every case, a phi looks through its pairs) and one per value it reads or writes
  // (an access chain only computes an offset). Summed per block for the executor's work
  // limit, which stops a batch whose loops never end.
  uint64_t instruction_cost(const Instruction& in, const std::vector<uint32_t>& ids) const {
    const auto value = [&](uint32_t id) {
      const Type& t = m_.types[m_.type_of[id]];
      return t.kind == Type::Kind::pointer ? 0 : elements_[m_.type_of[id]];
    };
    const auto ops = m_.operands_of(in);
    uint64_t cost = 1 + ops.size();
    switch (Op(in.op)) {
      case Op::OpAccessChain: case Op::OpInBoundsAccessChain: case Op::OpPtrAccessChain: break;
      case Op::OpLoad: case Op::OpVariable: cost += elements_of(in.result_type); break;
      case Op::OpStore: cost += ops.size() > 1 ? value(ops[1]) : 0; break;
      case Op::OpCopyMemory: cost += ops.empty() ? 0 : elements_of(m_.type_of[ops[0]]); break;
      default:
        if (in.result_type && m_.types[in.result_type].kind != Type::Kind::pointer) cost += elements_[in.result_type];
        for (uint32_t id : ids) cost += value(id);
        break;
    }
    return std::min(cost, saturated);
  }

  // The values one invocation holds (every result, parameter and variable: the executor
  // keeps them all for every lane of a batch) within max_invocation_values, and each
  // block's cost.
  TwinResult<void> check_limits() {
    uint64_t held = 0;
    for (uint32_t var : m_.variables) held += elements_of(m_.type_of[var]);
    for (auto& [id, f] : m_.functions) {
      for (uint32_t p : f.parameters) held += elements_of(m_.type_of[p]);
      for (Block& b : f.blocks)
        for (uint32_t i = b.first; i <= b.last && i < m_.instructions.size(); ++i) {
          const Instruction& in = m_.instructions[i];
          if (in.result && in.result_type) held += elements_of(in.result_type);
          b.cost = std::min(b.cost + instruction_cost(in, operand_ids_[i]), saturated);
        }
      held = std::min(held, saturated);
    }
    if (held > max_invocation_values)
      return std::unexpected(TwinError{.message = "the shader holds more than " + std::to_string(max_invocation_values) +
                                                  " values per invocation (its variables and results)"});
    return {};
  }

  TwinResult<void> global(Op op, std::span<const uint32_t> w) {
    using K = Type::Kind;
    auto type = [&](K kind) -> Type& {
      Type& t = m_.types[w[0]];
      t.kind = kind;
      return t;
    };
    switch (op) {   // counted before a constant's values are built
      case Op::OpConstantTrue: case Op::OpSpecConstantTrue: case Op::OpConstantFalse: case Op::OpSpecConstantFalse:
      case Op::OpConstant: case Op::OpSpecConstant: case Op::OpConstantComposite: case Op::OpSpecConstantComposite:
      case Op::OpConstantNull: case Op::OpUndef:
        if (auto ok = charge_constant(w[0]); !ok) return ok;
        break;
      default: break;
    }
    switch (op) {
      case Op::OpTypeVoid: type(K::void_); break;
      case Op::OpTypeBool: type(K::boolean); break;
      case Op::OpTypeInt: {
        Type& t = type(K::integer);
        t.width = w[1];
        t.is_signed = w[2] != 0;
        break;
      }
      case Op::OpTypeFloat: type(K::floating).width = w[1]; break;
      case Op::OpTypeVector: case Op::OpTypeMatrix: {
        Type& t = type(op == Op::OpTypeVector ? K::vector : K::matrix);
        t.element = w[1];
        t.count = w[2];
        break;
      }
      case Op::OpTypeArray: {
        Type& t = type(K::array);
        t.element = w[1];
        t.count = uint32_t(constant_value(w[2]));
        break;
      }
      case Op::OpTypeRuntimeArray: type(K::runtime_array).element = w[1]; break;
      case Op::OpTypeStruct: {
        Type& t = type(K::structure);
        t.members.assign(w.begin() + 1, w.end());
        const size_t n = t.members.size();
        t.member_offset.assign(n, 0);
        t.member_matrix_stride.assign(n, 0);
        t.member_row_major.assign(n, 0);
        t.member_flat.assign(n, 0);
        t.member_noperspective.assign(n, 0);
        t.member_builtin.assign(n, -1);
        t.member_location.assign(n, -1);
        break;
      }
      case Op::OpTypePointer: {
        Type& t = type(K::pointer);
        t.storage = w[1];
        t.element = w[2];
        break;
      }
      case Op::OpTypeFunction: type(K::function); break;
      case Op::OpTypeImage: {
        Type& t = type(K::image);
        t.element = w[1];
        t.dim = w[2];
        t.arrayed = w[4] != 0;
        break;
      }
      case Op::OpTypeSampler: type(K::sampler); break;
      case Op::OpTypeSampledImage: type(K::sampled_image).element = w[1]; break;
      case Op::OpConstantTrue: case Op::OpSpecConstantTrue: set_constant(w[1], w[0], {1.0}); break;
      case Op::OpConstantFalse: case Op::OpSpecConstantFalse: set_constant(w[1], w[0], {0.0}); break;
      case Op::OpConstant: case Op::OpSpecConstant: set_constant(w[1], w[0], {scalar(w[0], w.subspan(2))}); break;
      case Op::OpConstantComposite: case Op::OpSpecConstantComposite: {
        std::vector<double> slots;
        for (uint32_t part : w.subspan(2)) slots.insert(slots.end(), m_.constants[part].begin(), m_.constants[part].end());
        set_constant(w[1], w[0], std::move(slots));
        break;
      }
      case Op::OpConstantNull: case Op::OpUndef:
        layout(w[0]);
        set_constant(w[1], w[0], std::vector<double>(m_.types[w[0]].slots, 0.0));
        break;
      case Op::OpVariable:
        m_.type_of[w[1]] = w[0];
        m_.variables.push_back(w[1]);
        if (w.size() > 3) m_.variable_initializer[w[1]] = w[3];
        break;
      case Op::OpCapability: {
        // The executor knows each pointer id's variable and offset when it computes it: it
        // cannot follow pointers chosen (OpSelect, OpPhi), stored or loaded at run time.
        const auto capability = spv::Capability(w[0]);
        if (capability == spv::Capability::VariablePointers || capability == spv::Capability::VariablePointersStorageBuffer ||
            capability == spv::Capability::PhysicalStorageBufferAddresses)
          return std::unexpected(TwinError{.message = "the twin does not support variable or physical pointers"});
        break;
      }
      case Op::OpExtension: case Op::OpMemoryModel: case Op::OpModuleProcessed:
      case Op::OpSourceExtension:
      case Op::OpMemberName: case Op::OpDecorationGroup: case Op::OpExecutionModeId:
        break;
      case Op::OpExtInst:
        if (m_.non_semantic[w[2]]) break;   // debug info at module scope
        [[fallthrough]];
      default:
        return std::unexpected(TwinError{.message = "the twin does not support " + opcode_name(uint32_t(op)) +
                                                    " outside functions"});
    }
    if (op >= Op::OpTypeVoid && op <= Op::OpTypeForwardPointer && !w.empty() && w[0] < m_.bound) layout(w[0]);
    return {};
  }

  double scalar(uint32_t type_id, std::span<const uint32_t> words) {
    const Type& t = m_.types[type_id];
    if (t.kind == Type::Kind::floating) {
      if (t.width == 64 && words.size() >= 2) {
        const uint64_t bits = uint64_t(words[0]) | (uint64_t(words[1]) << 32);
        double d;
        std::memcpy(&d, &bits, 8);
        return d;
      }
      if (t.width == 16) {
        // binary16 literal: widen exactly.
        const uint32_t h = words[0] & 0xffff;
        const int exponent = int((h >> 10) & 0x1f);
        const double mantissa = double(h & 0x3ff);
        double v = exponent == 0 ? std::ldexp(mantissa, -24)
                   : exponent == 31 ? (mantissa != 0 ? std::numeric_limits<double>::quiet_NaN() : INFINITY)
                                    : std::ldexp(1024.0 + mantissa, exponent - 25);
        return (h & 0x8000) ? -v : v;
      }
      float f;
      std::memcpy(&f, &words[0], 4);
      return f;
    }
    if (t.width == 64 && words.size() >= 2) {
      const uint64_t bits = uint64_t(words[0]) | (uint64_t(words[1]) << 32);
      return t.is_signed ? double(int64_t(bits)) : double(bits);
    }
    return t.is_signed ? double(int32_t(words[0])) : double(words[0]);
  }

  void set_constant(uint32_t id, uint32_t type_id, std::vector<double> slots) {
    m_.is_constant[id] = 1;
    m_.type_of[id] = type_id;
    m_.constants[id] = std::move(slots);
  }

  Module& m_;
  std::vector<uint64_t> elements_;                 // by type id
  std::vector<std::vector<uint32_t>> operand_ids_;   // by instruction: its id operands
  uint64_t constant_values_ = 0;
  uint32_t last_source_file_ = 0;
  std::map<uint32_t, std::string> sources_;
  std::vector<RawInstruction> member_decorations_;
  std::vector<uint32_t> origin_lower_left_;
};

}  // namespace

std::string Module::name_of(uint32_t id) const {
  auto it = names.find(id);
  if (it != names.end() && !it->second.empty()) return it->second;
  // glslang names an anonymous block's variable "": its block type's name says which it is.
  if (id < type_of.size() && types[type_of[id]].kind == Type::Kind::pointer)
    if (auto block = names.find(types[type_of[id]].element); block != names.end() && !block->second.empty())
      return block->second;
  return "%" + std::to_string(id);
}

std::string opcode_name(uint32_t op) {
  for (const auto& entry : generated::opcode_names)
    if (entry.opcode == op) return entry.name;
  return "opcode " + std::to_string(op);
}

TwinResult<std::shared_ptr<const Module>> load_module(std::span<const uint32_t> spirv, const std::string& entry_point) {
  spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_0);
  spv_diagnostic diagnostic = nullptr;
  spv_const_binary_t binary{spirv.data(), spirv.size()};
  const spv_result_t valid = spvValidate(context, &binary, &diagnostic);
  std::string validation_error;
  if (valid != SPV_SUCCESS) validation_error = diagnostic ? diagnostic->error : "spirv-val rejected the module";
  spvDiagnosticDestroy(diagnostic);
  diagnostic = nullptr;
  if (!validation_error.empty()) {
    spvContextDestroy(context);
    return std::unexpected(TwinError{.message = "spirv-val: " + validation_error});
  }

  struct Collected {
    uint32_t bound = 0;
    std::vector<RawInstruction> raw;
  } collected;
  const auto on_header = [](void* user, spv_endianness_t, uint32_t, uint32_t, uint32_t, uint32_t id_bound,
                            uint32_t) -> spv_result_t {
    static_cast<Collected*>(user)->bound = id_bound;
    return SPV_SUCCESS;
  };
  const auto on_instruction = [](void* user, const spv_parsed_instruction_t* p) -> spv_result_t {
    RawInstruction r{p->opcode, std::vector<uint32_t>(p->words + 1, p->words + p->num_words), {}};
    for (uint16_t i = 0; i < p->num_operands; ++i)
      if (is_id(p->operands[i].type)) r.ids.push_back(uint16_t(p->operands[i].offset - 1));
    static_cast<Collected*>(user)->raw.push_back(std::move(r));
    return SPV_SUCCESS;
  };
  const spv_result_t parsed =
      spvBinaryParse(context, &collected, spirv.data(), spirv.size(), on_header, on_instruction, &diagnostic);
  std::string parse_error;
  if (parsed != SPV_SUCCESS) parse_error = diagnostic ? diagnostic->error : "the module cannot be parsed";
  spvDiagnosticDestroy(diagnostic);
  spvContextDestroy(context);
  if (!parse_error.empty()) return std::unexpected(TwinError{.message = "spvBinaryParse: " + parse_error});

  // A compiler's ids are dense (each takes two words or more): those modules keep theirs.
  if (collected.bound > spirv.size()) collected.bound = compact_ids(collected.raw);

  auto module = std::make_shared<Module>();
  Module& m = *module;
  m.bound = collected.bound;
  m.types.resize(m.bound);
  m.decorations.resize(m.bound);
  m.is_constant.resize(m.bound);
  m.constants.resize(m.bound);
  m.type_of.resize(m.bound);
  m.variable_initializer.resize(m.bound);
  m.glsl_std450.resize(m.bound);
  m.non_semantic.resize(m.bound);
  Decoder decoder(m);
  // ArrayStride decorates a type id: note which id each OpDecorate is about before decoding it.
  for (const RawInstruction& r : collected.raw)
    if (spv::Op(r.op) == spv::Op::OpDecorate && spv::Decoration(r.words[1]) == spv::Decoration::ArrayStride)
      m.types[r.words[0]].array_stride = r.words[2];
  if (auto ok = decoder.decode(collected.raw, entry_point); !ok) return std::unexpected(ok.error());
  return std::shared_ptr<const Module>(std::move(module));
}

}  // namespace twin
