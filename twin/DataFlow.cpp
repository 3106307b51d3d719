#include "twin/DataFlow.h"

#include <spirv/unified1/spirv.hpp11>

#include <algorithm>
#include <functional>
#include <map>
#include <set>

#include "twin/InstructionText.h"

namespace twin {
namespace {

using Op = spv::Op;

bool own_memory(uint32_t storage) {
  const auto s = spv::StorageClass(storage);
  return s == spv::StorageClass::Function || s == spv::StorageClass::Private || s == spv::StorageClass::Output;
}

}  // namespace

bool is_value(const Module& m, const DataFlow& flow, uint32_t id) {
  if (id == 0 || id >= m.bound || m.type_of[id] == 0) return false;
  if (!m.is_constant[id] && flow.defining[id] < 0) return false;
  const Type& t = m.types[m.type_of[id]];
  return t.kind != Type::Kind::pointer && t.kind != Type::Kind::function && t.kind != Type::Kind::void_;
}

DataFlow data_flow(const Module& m) {
  DataFlow f;
  const size_t count = m.instructions.size();
  f.defining.assign(m.bound, -1);
  f.kind.assign(count, DataFlow::Kind::computed);
  f.inputs.assign(count, {});
  f.output.assign(count, 0);
  f.reaches_output.assign(count, 0);
  f.read_variable.assign(count, 0);
  for (size_t i = 0; i < count; ++i)
    if (const uint32_t r = m.instructions[i].result; r && r < m.bound) f.defining[r] = int32_t(i);

  // Function parameters: which call arguments each receives; and each function's returns.
  std::map<uint32_t, std::vector<uint32_t>> arguments;   // parameter id -> argument ids
  std::map<uint32_t, std::vector<uint32_t>> returned;    // function id -> returned ids
  for (const auto& [id, function] : m.functions)
    for (const Block& b : function.blocks)
      for (uint32_t i = b.first; i <= b.last && i < count; ++i) {
        const Instruction& in = m.instructions[i];
        if (Op(in.op) == Op::OpReturnValue) returned[id].push_back(m.operands_of(in)[0]);
        if (Op(in.op) != Op::OpFunctionCall) continue;
        const auto ops = m.operands_of(in);
        auto callee = m.functions.find(ops[0]);
        if (callee == m.functions.end()) continue;
        for (size_t k = 0; k + 1 < ops.size() && k < callee->second.parameters.size(); ++k)
          arguments[callee->second.parameters[k]].push_back(ops[k + 1]);
      }

  // The variables a pointer may point into.
  std::map<uint32_t, std::set<uint32_t>> bases_memo;
  std::function<const std::set<uint32_t>&(uint32_t)> bases = [&](uint32_t pointer) -> const std::set<uint32_t>& {
    if (auto it = bases_memo.find(pointer); it != bases_memo.end()) return it->second;
    std::set<uint32_t>& out = bases_memo[pointer];   // empty while being computed: breaks cycles
    if (auto a = arguments.find(pointer); a != arguments.end()) {
      std::set<uint32_t> all;
      for (uint32_t arg : a->second) all.insert(bases(arg).begin(), bases(arg).end());
      return bases_memo[pointer] = std::move(all);
    }
    const int32_t d = pointer < m.bound ? f.defining[pointer] : -1;
    if (d < 0) return out = {pointer};   // a module-scope variable
    const Instruction& in = m.instructions[size_t(d)];
    switch (Op(in.op)) {
      case Op::OpAccessChain:
      case Op::OpInBoundsAccessChain:
      case Op::OpPtrAccessChain:
      case Op::OpCopyObject: {
        std::set<uint32_t> from = bases(m.operands_of(in)[0]);
        return bases_memo[pointer] = std::move(from);
      }
      default: return out = {pointer};
    }
  };
  const auto storage = [&](uint32_t variable) {
    const uint32_t t = variable < m.bound ? m.type_of[variable] : 0;
    return t ? m.types[t].storage : 0;
  };

  // A value id's instructions: its own, or for a value parameter its arguments'.
  std::function<void(uint32_t, std::vector<uint32_t>&, int)> definers = [&](uint32_t id, std::vector<uint32_t>& out, int depth) {
    if (id >= m.bound || depth > 8) return;
    if (f.defining[id] >= 0) {
      out.push_back(uint32_t(f.defining[id]));
    } else if (auto a = arguments.find(id); a != arguments.end()) {
      for (uint32_t arg : a->second) definers(arg, out, depth + 1);
    }
  };

  std::map<uint32_t, std::vector<uint32_t>> stored;   // variable -> instructions whose values are stored in it
  for (size_t i = 0; i < count; ++i) {
    const Instruction& in = m.instructions[i];
    if (Op(in.op) != Op::OpStore) continue;
    const auto ops = m.operands_of(in);
    std::vector<uint32_t> values;
    definers(ops[1], values, 0);
    for (uint32_t variable : bases(ops[0])) {
      auto& into = stored[variable];
      into.insert(into.end(), values.begin(), values.end());
      if (spv::StorageClass(storage(variable)) == spv::StorageClass::Output)
        for (uint32_t v : values) f.output[v] = 1;
    }
  }

  for (size_t i = 0; i < count; ++i) {
    const Instruction& in = m.instructions[i];
    if (!in.result || !in.result_type) continue;
    std::vector<uint32_t>& inputs = f.inputs[i];
    const auto ops = m.operands_of(in);
    switch (Op(in.op)) {
      case Op::OpLoad: {
        const std::set<uint32_t>& from = bases(ops[0]);
        const bool own = std::ranges::any_of(from, [&](uint32_t v) { return own_memory(storage(v)); });
        f.kind[i] = own ? DataFlow::Kind::copy : DataFlow::Kind::read;
        for (uint32_t v : from) {
          if (own) {
            auto it = stored.find(v);
            if (it != stored.end()) inputs.insert(inputs.end(), it->second.begin(), it->second.end());
          } else {
            f.read_variable[i] = v;
          }
        }
        break;
      }
      case Op::OpFunctionCall:
        f.kind[i] = DataFlow::Kind::copy;
        if (auto r = returned.find(ops[0]); r != returned.end())
          for (uint32_t id : r->second) definers(id, inputs, 0);
        break;
      case Op::OpCopyObject:
        f.kind[i] = DataFlow::Kind::copy;
        definers(ops[0], inputs, 0);
        break;
      case Op::OpPhi:
        for (size_t k = 0; k + 1 < ops.size(); k += 2) definers(ops[k], inputs, 0);
        break;
      default:
        for (uint32_t id : value_operands(m, in))
          if (is_value(m, f, id) || arguments.contains(id)) definers(id, inputs, 0);
    }
    std::ranges::sort(inputs);
    inputs.erase(std::unique(inputs.begin(), inputs.end()), inputs.end());
  }

  // What the outputs depend on, back from the stored values.
  std::vector<uint32_t> work;
  for (size_t i = 0; i < count; ++i)
    if (f.output[i]) f.reaches_output[i] = 1, work.push_back(uint32_t(i));
  while (!work.empty()) {
    const uint32_t i = work.back();
    work.pop_back();
    for (uint32_t j : f.inputs[i])
      if (!f.reaches_output[j]) f.reaches_output[j] = 1, work.push_back(j);
  }
  return f;
}

}  // namespace twin
