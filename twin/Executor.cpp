#include "twin/Executor.h"

#include <spirv/unified1/spirv.hpp11>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

namespace twin {

namespace {

using spv::Op;
using K = Type::Kind;

bool contains(const std::vector<uint32_t>& v, uint32_t x) { return std::find(v.begin(), v.end(), x) != v.end(); }

std::vector<uint32_t> with(std::vector<uint32_t> v, std::initializer_list<uint32_t> more) {
  for (uint32_t x : more)
    if (x && !contains(v, x)) v.push_back(x);
  return v;
}

// The integer a slot holds, wrapped to the type's width and signedness.
double wrap_integer(const Type& t, int64_t x) {
  if (t.kind == K::boolean) return x != 0;
  if (t.width == 64) return t.is_signed ? double(x) : double(uint64_t(x));
  return t.is_signed ? double(int32_t(uint32_t(uint64_t(x)))) : double(uint32_t(uint64_t(x)));
}

// -x as the device computes it: INT64_MIN stays itself instead of overflowing.
int64_t wrapping_negate(int64_t x) { return int64_t(0 - uint64_t(x)); }

template <typename T>
int64_t as_integer(T value) {
  const double x = double(value);
  if (!(x == x)) return 0;
  if (x >= 9.2e18) return std::numeric_limits<int64_t>::max();
  if (x <= -9.2e18) return std::numeric_limits<int64_t>::min();
  return int64_t(x);
}

// Bits of a slot seen as the 32- or 64-bit type `t`.
template <typename T>
uint64_t bits_of(const Type& t, T value) {
  const double x = double(value);
  if (t.kind == K::floating) {
    if (t.width == 64) return std::bit_cast<uint64_t>(x);
    return std::bit_cast<uint32_t>(float(x));
  }
  const int64_t i = as_integer(x);
  return t.width == 64 ? uint64_t(i) : uint64_t(uint32_t(uint64_t(i)));
}

double from_bits(const Type& t, uint64_t bits) {
  if (t.kind == K::floating) {
    if (t.width == 64) return std::bit_cast<double>(bits);
    return std::bit_cast<float>(uint32_t(bits));
  }
  return wrap_integer(t, int64_t(bits));
}

// Whether every slot of type `id` holds a float: relaxed memory rounds only those to half
// (a mediump int is a 16-bit integer on a GPU, exact in its range, not a binary16 float).
bool float_valued(const Module& m, uint32_t id) {
  const Type& t = m.types[id];
  switch (t.kind) {
    case K::floating: return true;
    case K::vector: case K::matrix: case K::array: return float_valued(m, t.element);
    case K::structure:
      return std::all_of(t.members.begin(), t.members.end(), [&](uint32_t member) { return float_valued(m, member); });
    default: return false;
  }
}

// Float -> integer conversion: GPUs saturate out-of-range values; NaN gives 0.
template <typename T>
double float_to_integer(const Type& t, T value) {
  const double x = double(value);
  if (!(x == x)) return 0;
  const double truncated = trunc(x);
  if (t.is_signed) return std::clamp(truncated, -2147483648.0, 2147483647.0);
  return std::clamp(truncated, 0.0, 4294967295.0);
}

}  // namespace

template <typename Real>
typename BasicExecutor<Real>::Lanes BasicExecutor<Real>::Arrivals::take(uint32_t label) {
  for (auto it = at.begin(); it != at.end(); ++it)
    if (it->first == label) {
      Lanes lanes = std::move(it->second);
      at.erase(it);
      return lanes;
    }
  return {};
}

template <typename Real>
void BasicExecutor<Real>::Arrivals::add(uint32_t label, const Lanes& lanes) {
  if (lanes.empty()) return;
  for (auto& [l, existing] : at)
    if (l == label) {
      Lanes merged;
      std::merge(existing.begin(), existing.end(), lanes.begin(), lanes.end(), std::back_inserter(merged));
      existing = std::move(merged);
      return;
    }
  at.emplace_back(label, lanes);
}

template <typename Real>
BasicExecutor<Real>::BasicExecutor(const Module& module, const BoundResources& resources, Precision precision)
    : m_(module), resources_(resources), precision_(precision) {
  pointers_.resize(m_.bound);
  constants_.resize(m_.bound);
  for (uint32_t id = 0; id < m_.bound; ++id) constants_[id].assign(m_.constants[id].begin(), m_.constants[id].end());
  memory_.resize(m_.bound);
  // Registers: every non-pointer result of a function body, and the value parameters.
  std::vector<uint32_t> slot_offset(m_.bound, 0);
  auto add_register = [&](uint32_t id, uint32_t type) {
    const Type& t = m_.types[type];
    if (t.kind == K::pointer || t.kind == K::void_ || t.kind == K::none) return;
    slot_offset[id] = register_slots_;
    register_slots_ += t.slots;
  };
  for (const Instruction& in : m_.instructions)
    if (in.result && in.result_type) add_register(in.result, in.result_type);
  for (const auto& [id, f] : m_.functions)
    for (uint32_t p : f.parameters) add_register(p, m_.type_of[p]);
  register_slot_ = std::move(slot_offset);
  register_base_ = register_slot_;   // scaled by the lane count in begin()
  for (uint32_t var : m_.variables) pointers_[var] = Pointer{.variable = var};

  rounding_.assign(m_.instructions.size(), 0);
  for (size_t i = 0; i < m_.instructions.size(); ++i) {
    const Instruction& in = m_.instructions[i];
    if (!in.result_type || precision_ == Precision::exact) continue;
    const Type& t = m_.types[in.result_type];
    const Type& scalar = t.kind == K::vector || t.kind == K::matrix
                             ? (t.kind == K::matrix ? m_.types[m_.types[t.element].element] : m_.types[t.element])
                             : t;
    if (scalar.kind != K::floating) continue;
    rounding_[i] = precision_ == Precision::half && m_.decorations[in.result].relaxed ? 2 : 1;
  }
}

template <typename Real>
typename BasicExecutor<Real>::Src BasicExecutor<Real>::src(uint32_t id) const {
  if (m_.is_constant[id]) return {constants_[id].data(), 1, 0};
  return {&registers_[register_base_[id]], lanes_, 1};
}

template <typename Real>
TwinError BasicExecutor<Real>::error(const Instruction& in, const std::string& message) const {
  const SourceLine& line = m_.lines[in.line];
  return TwinError{.message = message, .file = line.file, .line = line.line};
}

template <typename Real>
Real* BasicExecutor<Real>::input(uint32_t variable) { return memory_[variable].slots.data(); }
template <typename Real>
const Real* BasicExecutor<Real>::output(uint32_t variable) const { return memory_[variable].slots.data(); }

namespace {

// Decodes a block member of type `t` at byte `offset` into slots (std140/std430 as the
// module's Offset, ArrayStride and MatrixStride decorations lay it out).
void decode_memory(const Module& m, uint32_t type_id, const BoundResources::Buffer& buffer, size_t offset,
                   uint32_t matrix_stride, bool row_major, std::vector<double>& out) {
  const Type& t = m.types[type_id];
  const std::span<const std::byte> bytes = buffer.bytes;
  auto read32 = [&](size_t at) -> uint32_t {
    uint32_t v = 0;
    if (at + 4 <= bytes.size()) std::memcpy(&v, bytes.data() + at, 4);
    return v;
  };
  switch (t.kind) {
    case K::floating:
      if (t.width == 64) {
        uint64_t v = 0;
        if (offset + 8 <= bytes.size()) std::memcpy(&v, bytes.data() + offset, 8);
        out.push_back(std::bit_cast<double>(v));
      } else if (offset % 4 == 0 && offset / 4 < buffer.words.size()) {
        out.push_back(buffer.words[offset / 4]);
      } else {
        out.push_back(std::bit_cast<float>(read32(offset)));
      }
      return;
    case K::integer: out.push_back(t.is_signed ? double(int32_t(read32(offset))) : double(read32(offset))); return;
    case K::boolean: out.push_back(read32(offset) != 0); return;
    case K::vector: {
      const uint32_t size = m.types[t.element].width / 8;
      for (uint32_t i = 0; i < t.count; ++i) decode_memory(m, t.element, buffer, offset + i * size, 0, false, out);
      return;
    }
    case K::matrix: {
      const Type& column = m.types[t.element];
      const uint32_t scalar_size = m.types[column.element].width / 8;
      for (uint32_t c = 0; c < t.count; ++c)
        for (uint32_t r = 0; r < column.count; ++r) {
          const size_t at = row_major ? offset + r * matrix_stride + c * scalar_size
                                      : offset + c * matrix_stride + r * scalar_size;
          decode_memory(m, column.element, buffer, at, 0, false, out);
        }
      return;
    }
    case K::array:
      for (uint32_t i = 0; i < t.count; ++i)
        decode_memory(m, t.element, buffer, offset + size_t(i) * t.array_stride, matrix_stride, row_major, out);
      return;
    case K::structure:
      for (size_t i = 0; i < t.members.size(); ++i)
        decode_memory(m, t.members[i], buffer, offset + t.member_offset[i], t.member_matrix_stride[i],
                      t.member_row_major[i] != 0, out);
      return;
    default: out.push_back(0); return;
  }
}

}  // namespace

template <typename Real>
TwinResult<void> BasicExecutor<Real>::begin(uint32_t lanes, bool quads) {
  lanes_ = lanes;
  quads_ = quads;
  // Registers are written before they are read (SSA), so a new batch need not clear them.
  if (registers_.size() < size_t(register_slots_) * lanes) registers_.resize(size_t(register_slots_) * lanes);
  // Register r's slot s of lane l is at (slot_r + s) * lanes + l.
  if (lanes != based_lanes_) {
    for (size_t id = 0; id < register_base_.size(); ++id) register_base_[id] = register_slot_[id] * lanes;
    based_lanes_ = lanes;
  }
  predecessor_.assign(lanes, 0);
  discarded_.assign(lanes, 0);
  for (uint32_t var : m_.variables) {
    const Type& pointer = m_.types[m_.type_of[var]];
    const Type& t = m_.types[pointer.element];
    Memory& mem = memory_[var];
    const auto storage = spv::StorageClass(pointer.storage);
    const Decoration& d = m_.decorations[var];
    const bool opaque = t.kind == K::image || t.kind == K::sampler || t.kind == K::sampled_image ||
                        (t.kind == K::array && (m_.types[t.element].kind == K::sampled_image ||
                                                 m_.types[t.element].kind == K::image));
    if (storage == spv::StorageClass::Uniform || storage == spv::StorageClass::UniformConstant ||
        storage == spv::StorageClass::PushConstant || storage == spv::StorageClass::StorageBuffer) {
      if (mem.shared) continue;   // decoded once, for every batch
      mem.shared = true;
      mem.lanes = 1;
      mem.slots.clear();
      if (opaque) {
        auto it = resources_.handles.find({uint32_t(d.set), uint32_t(d.binding)});
        if (it == resources_.handles.end())
          return std::unexpected(TwinError{.message = "nothing is bound to " + m_.name_of(var) + " (set " +
                                                      std::to_string(d.set) + ", binding " + std::to_string(d.binding) + ")"});
        mem.slots.assign(t.slots, Real(it->second));
      } else if (storage == spv::StorageClass::PushConstant) {
        std::vector<double> slots;
        decode_memory(m_, pointer.element, resources_.push_constants, 0, 0, false, slots);
        mem.slots.assign(slots.begin(), slots.end());
      } else {
        auto it = resources_.buffers.find({uint32_t(d.set), uint32_t(d.binding)});
        if (it == resources_.buffers.end())
          return std::unexpected(TwinError{.message = "no buffer is bound to " + m_.name_of(var) + " (set " +
                                                      std::to_string(d.set) + ", binding " + std::to_string(d.binding) + ")"});
        std::vector<double> slots;
        decode_memory(m_, pointer.element, it->second, 0, d.matrix_stride, d.row_major, slots);
        mem.slots.assign(slots.begin(), slots.end());
      }
      continue;
    }
    mem.lanes = lanes;
    // Outputs start at zero, so a component the shader never writes is the same in every
    // batch; inputs are filled by the caller and private variables written before read.
    if (mem.slots.size() < size_t(t.slots) * lanes) mem.slots.resize(size_t(t.slots) * lanes);
    if (storage == spv::StorageClass::Output) std::fill_n(mem.slots.begin(), size_t(t.slots) * lanes, 0.0);
    if (uint32_t init = m_.variable_initializer[var]; init && m_.is_constant[init])
      for (uint32_t s = 0; s < t.slots; ++s)
        std::fill_n(mem.slots.begin() + std::ptrdiff_t(s) * lanes, lanes, m_.constants[init][s]);
  }
  return {};
}

template <typename Real>
TwinResult<void> BasicExecutor<Real>::run() {
  Lanes all(lanes_);
  for (uint32_t l = 0; l < lanes_; ++l) all[l] = uint16_t(l);
  const Function& entry = m_.functions.at(m_.entry_function);
  work_ = 0;
  Arrivals arrivals;
  return run_region(entry, entry.blocks.front().label, std::move(all), {}, arrivals);
}

template <typename Real>
std::vector<std::pair<uint32_t, typename BasicExecutor<Real>::Lanes>> BasicExecutor<Real>::branch_targets(const Block& block, const Lanes& lanes) {
  const Instruction& term = m_.instructions[block.last];
  const auto ops = m_.operands_of(term);
  std::vector<std::pair<uint32_t, Lanes>> targets;
  auto add = [&](uint32_t label, uint16_t lane) {
    for (auto& [l, ls] : targets)
      if (l == label) {
        ls.push_back(lane);
        return;
      }
    targets.push_back({label, Lanes{lane}});
  };
  if (Op(term.op) == Op::OpBranch) {
    targets.push_back({ops[0], lanes});
  } else if (Op(term.op) == Op::OpBranchConditional) {
    const Src c = src(ops[0]);
    for (uint16_t l : lanes) add(c.at(0, l) != 0 ? ops[1] : ops[2], l);
  } else {   // OpSwitch selector default (literal label)*
    const Src s = src(ops[0]);
    const Type& t = m_.types[m_.type_of[ops[0]]];
    const size_t literal_words = t.width == 64 ? 2 : 1;
    for (uint16_t l : lanes) {
      const int64_t v = as_integer(s.at(0, l));
      uint32_t target = ops[1];
      for (size_t i = 2; i + literal_words < ops.size() + 0 && i + literal_words <= ops.size() - 1; i += literal_words + 1) {
        int64_t literal = t.is_signed ? int64_t(int32_t(ops[i])) : int64_t(ops[i]);
        if (literal_words == 2) literal = int64_t(uint64_t(ops[i]) | (uint64_t(ops[i + 1]) << 32));
        if (literal == v) {
          target = ops[i + literal_words];
          break;
        }
      }
      add(target, l);
    }
  }
  for (auto& [label, ls] : targets)
    for (uint16_t l : ls) predecessor_[l] = block.label;
  return targets;
}

template <typename Real>
TwinResult<void> BasicExecutor<Real>::run_block_body(const Block& block, Lanes& lanes) {
  work_ += block.cost;
  if (work_ > work_limit_)
    return std::unexpected(error(m_.instructions[block.first], "the batch exceeded the work limit (" +
                                                                 std::to_string(work_limit_) + "): a loop that does not end?"));
  uint32_t first = block.first;
  // A block's OpPhis are parallel copies: one may take another phi of the same block from
  // the back edge (a swap in a loop), so every phi reads its value before any is written.
  uint32_t phis_end = first;
  while (phis_end < block.last && Op(m_.instructions[phis_end].op) == Op::OpPhi) ++phis_end;
  if (phis_end - first > 1 && !lanes.empty()) {
    std::vector<Real> read;
    for (uint32_t i = first; i < phis_end; ++i) {
      const Instruction& in = m_.instructions[i];
      const auto ops = m_.operands_of(in);
      const Src old = src(in.result);
      for (uint32_t s = 0; s < slots_of(in.result); ++s)
        for (uint16_t l : lanes) {
          Real value = old.at(s, l);
          for (size_t k = 0; k + 1 < ops.size(); k += 2)
            if (ops[k + 1] == predecessor_[l]) {
              value = src(ops[k]).at(s, l);
              break;
            }
          read.push_back(value);
        }
    }
    size_t at = 0;
    for (uint32_t i = first; i < phis_end; ++i) {
      const uint32_t result = m_.instructions[i].result;
      Real* d = dst(result);
      for (uint32_t s = 0; s < slots_of(result); ++s)
        for (uint16_t l : lanes) d[s * lanes_ + l] = read[at++];
      if (observer_) observe_result(i, lanes);
    }
    first = phis_end;
  }
  for (uint32_t i = first; i < block.last && !lanes.empty(); ++i)
    if (auto ok = execute(i, lanes); !ok) return ok;
  return {};
}

template <typename Real>
TwinResult<void> BasicExecutor<Real>::run_region(const Function& f, uint32_t label, Lanes lanes,
                                      const std::vector<uint32_t>& stops, Arrivals& out) {
  while (!lanes.empty()) {
    if (contains(stops, label)) {
      out.add(label, lanes);
      return {};
    }
    const Block& block = f.blocks[f.block_of.at(label)];
    if (auto ok = run_block_body(block, lanes); !ok) return ok;
    if (lanes.empty()) return {};
    const Instruction& term = m_.instructions[block.last];
    switch (Op(term.op)) {
      case Op::OpReturn: out.returned.insert(out.returned.end(), lanes.begin(), lanes.end()); return {};
      case Op::OpReturnValue: {
        const uint32_t value = m_.operands_of(term)[0];
        if (!call_results_.empty()) {
          const Src v = src(value);
          Real* d = dst(call_results_.back());
          const uint32_t n = slots_of(value);
          for (uint16_t l : lanes)
            for (uint32_t s = 0; s < n; ++s) d[s * lanes_ + l] = v.at(s, l);
        }
        out.returned.insert(out.returned.end(), lanes.begin(), lanes.end());
        return {};
      }
      case Op::OpKill: case Op::OpTerminateInvocation:
        for (uint16_t l : lanes) discarded_[l] = 1;
        return {};
      case Op::OpUnreachable: return {};
      case Op::OpBranch: case Op::OpBranchConditional: case Op::OpSwitch: break;
      default: return std::unexpected(error(term, "the twin does not support " + opcode_name(term.op) + " here"));
    }
    auto targets = branch_targets(block, lanes);
    if (block.continue_target) {   // a loop header
      Lanes exits;
      if (auto ok = run_loop(f, block, std::move(targets), stops, out, exits); !ok) return ok;
      lanes = std::move(exits);
      label = block.merge;
      continue;
    }
    if (block.merge) {   // a selection: every side runs to the merge block, then the lanes go on together
      Arrivals inner;
      const auto inner_stops = with(stops, {block.merge});
      for (auto& [target, ls] : targets)
        if (auto ok = run_region(f, target, std::move(ls), inner_stops, inner); !ok) return ok;
      lanes = inner.take(block.merge);
      for (auto& [l, ls] : inner.at) out.add(l, ls);
      out.returned.insert(out.returned.end(), inner.returned.begin(), inner.returned.end());
      std::sort(lanes.begin(), lanes.end());
      label = block.merge;
      continue;
    }
    if (targets.size() == 1) {
      label = targets[0].first;
      lanes = std::move(targets[0].second);
      continue;
    }
    // A conditional break or continue: each side leaves for its own stop.
    for (auto& [target, ls] : targets)
      if (auto ok = run_region(f, target, std::move(ls), stops, out); !ok) return ok;
    return {};
  }
  return {};
}

template <typename Real>
TwinResult<void> BasicExecutor<Real>::run_loop(const Function& f, const Block& header,
                                    std::vector<std::pair<uint32_t, Lanes>> targets,
                                    const std::vector<uint32_t>& stops, Arrivals& out, Lanes& exits) {
  const uint32_t merge = header.merge, continue_target = header.continue_target;
  const auto body_stops = with(stops, {merge, continue_target});
  const auto continue_stops = with(stops, {merge, header.label});
  for (uint64_t iteration = 0;; ++iteration) {
    if (iteration > (uint64_t{1} << 24))
      return std::unexpected(error(m_.instructions[header.last], "a loop ran more than 2^24 iterations"));
    Arrivals body;
    for (auto& [target, ls] : targets)
      if (auto ok = run_region(f, target, std::move(ls), body_stops, body); !ok) return ok;
    Lanes exiting = body.take(merge);
    Lanes continuing = body.take(continue_target);
    for (auto& [l, ls] : body.at) out.add(l, ls);
    out.returned.insert(out.returned.end(), body.returned.begin(), body.returned.end());
    Lanes again;
    if (!continuing.empty()) {
      std::sort(continuing.begin(), continuing.end());
      Arrivals latch;
      if (auto ok = run_region(f, continue_target, std::move(continuing), continue_stops, latch); !ok) return ok;
      Lanes more = latch.take(merge);
      exiting.insert(exiting.end(), more.begin(), more.end());
      again = latch.take(header.label);
      for (auto& [l, ls] : latch.at) out.add(l, ls);
      out.returned.insert(out.returned.end(), latch.returned.begin(), latch.returned.end());
    }
    exits.insert(exits.end(), exiting.begin(), exiting.end());
    if (again.empty()) break;
    std::sort(again.begin(), again.end());
    if (auto ok = run_block_body(header, again); !ok) return ok;
    targets = branch_targets(header, again);
  }
  std::sort(exits.begin(), exits.end());
  return {};
}

template <typename Real>
TwinResult<void> BasicExecutor<Real>::call(const Instruction& in, Lanes& lanes) {
  const auto ops = m_.operands_of(in);
  auto it = m_.functions.find(ops[0]);
  if (it == m_.functions.end()) return std::unexpected(error(in, "call of an unknown function"));
  const Function& callee = it->second;
  for (size_t i = 0; i < callee.parameters.size() && i + 1 < ops.size(); ++i) {
    const uint32_t parameter = callee.parameters[i], argument = ops[i + 1];
    if (m_.types[m_.type_of[parameter]].kind == K::pointer) {
      pointers_[parameter] = pointers_[argument];
      continue;
    }
    const Src a = src(argument);
    Real* d = dst(parameter);
    const uint32_t n = slots_of(parameter);
    for (uint16_t l : lanes)
      for (uint32_t s = 0; s < n; ++s) d[s * lanes_ + l] = a.at(s, l);
  }
  call_results_.push_back(in.result);
  Arrivals arrivals;
  auto ok = run_region(callee, callee.blocks.front().label, lanes, {}, arrivals);
  call_results_.pop_back();
  if (!ok) return ok;
  lanes = std::move(arrivals.returned);
  std::sort(lanes.begin(), lanes.end());
  return {};
}

template <typename Real>
void BasicExecutor<Real>::observe_result(uint32_t index, const Lanes& lanes) {
  const Instruction& in = m_.instructions[index];
  if (!in.result || !in.result_type || !std::binary_search(lanes.begin(), lanes.end(), uint16_t(observed_lane_)))
    return;
  const Type& t = m_.types[in.result_type];
  if (t.kind == K::pointer || t.kind == K::void_ || t.slots == 0) return;
  std::vector<double> values(t.slots);
  const Src v = src(in.result);
  for (uint32_t s = 0; s < t.slots; ++s) values[s] = double(v.at(s, observed_lane_));
  observer_->value(index, values);
}

template <typename Real>
TwinResult<void> BasicExecutor<Real>::execute(uint32_t index, Lanes& lanes) {
  auto ok = execute_op(index, lanes);
  if (ok && observer_) observe_result(index, lanes);
  return ok;
}

template <typename Real>
TwinResult<void> BasicExecutor<Real>::execute_op(uint32_t index, Lanes& lanes) {
  const Instruction& in = m_.instructions[index];
  const auto ops = m_.operands_of(in);
  const Op op = Op(in.op);
  const uint32_t L = lanes_;
  const Type& rt = m_.types[in.result_type];
  const uint32_t n = rt.slots;

  auto unary = [&](auto f) {
    const Src a = src(ops[0]);
    Real* d = dst(in.result);
    for (uint32_t s = 0; s < n; ++s)
      for (uint16_t l : lanes) d[s * L + l] = rounded(index, f(a.at(s, l)));
  };
  // Component-wise on two operands; a scalar operand (one slot) applies to every component.
  auto binary = [&](auto f) {
    const Src a = src(ops[0]), b = src(ops[1]);
    const bool a_scalar = slots_of(ops[0]) == 1 && n > 1, b_scalar = slots_of(ops[1]) == 1 && n > 1;
    Real* d = dst(in.result);
    for (uint32_t s = 0; s < n; ++s)
      for (uint16_t l : lanes) d[s * L + l] = rounded(index, f(a.at(a_scalar ? 0 : s, l), b.at(b_scalar ? 0 : s, l)));
  };
  // Integer and logical operations: no rounding, the result wrapped to its type.
  const Type& scalar_type = rt.kind == K::vector ? m_.types[rt.element] : rt;
  auto integer_binary = [&](auto f) {
    const Src a = src(ops[0]), b = src(ops[1]);
    Real* d = dst(in.result);
    for (uint32_t s = 0; s < n; ++s)
      for (uint16_t l : lanes) d[s * L + l] = wrap_integer(scalar_type, f(as_integer(a.at(s, l)), as_integer(b.at(s, l))));
  };
  auto compare = [&](auto f) {
    const Src a = src(ops[0]), b = src(ops[1]);
    Real* d = dst(in.result);
    for (uint32_t s = 0; s < n; ++s)
      for (uint16_t l : lanes) d[s * L + l] = f(a.at(s, l), b.at(s, l)) ? 1.0 : 0.0;
  };
  auto unsigned_of = [&](uint32_t id, Real x) -> uint64_t {
    const Type& t = m_.types[m_.type_of[id]];
    const Type& st = t.kind == K::vector ? m_.types[t.element] : t;
    return st.width == 64 ? uint64_t(as_integer(x)) : uint64_t(uint32_t(uint64_t(as_integer(x))));
  };
  auto signed_of = [&](uint32_t id, Real x) -> int64_t {
    const Type& t = m_.types[m_.type_of[id]];
    const Type& st = t.kind == K::vector ? m_.types[t.element] : t;
    return st.width == 64 ? as_integer(x) : int64_t(int32_t(uint32_t(uint64_t(as_integer(x)))));
  };

  switch (op) {
    case Op::OpNop: case Op::OpLine: case Op::OpNoLine: case Op::OpSelectionMerge: case Op::OpLoopMerge:
      return {};
    case Op::OpVariable: {
      Pointer& p = pointers_[in.result];
      p = Pointer{.variable = in.result};
      Memory& mem = memory_[in.result];
      const Type& t = m_.types[rt.element];
      // A function's variable is written before it is read: a new batch need not clear it.
      if (mem.slots.size() < size_t(t.slots) * L) mem.slots.resize(size_t(t.slots) * L);
      mem.lanes = L;
      if (ops.size() > 1) {   // an initializer
        const Src init = src(ops[1]);
        for (uint32_t s = 0; s < t.slots; ++s)
          for (uint16_t l : lanes) mem.slots[s * L + l] = init.at(s, l);
      }
      return {};
    }
    case Op::OpAccessChain: case Op::OpInBoundsAccessChain: {
      Pointer p = pointers_[ops[0]];
      uint32_t type = m_.types[m_.type_of[ops[0]]].element;
      for (size_t i = 1; i < ops.size(); ++i) {
        const Type& t = m_.types[type];
        const uint32_t index_id = ops[i];
        if (t.kind == K::structure) {
          const uint32_t member = uint32_t(m_.constants[index_id][0]);
          if (member >= t.members.size()) return std::unexpected(error(in, "struct member index out of range"));
          if (p.lane_offset.empty()) p.offset += t.member_slots[member];
          else for (uint16_t l : lanes) p.lane_offset[l] += t.member_slots[member];
          type = t.members[member];
          continue;
        }
        const uint32_t element = t.element;
        const uint32_t stride = m_.types[element].slots;
        const uint32_t count = t.kind == K::runtime_array ? 1 : t.count;
        if (m_.is_constant[index_id]) {
          const int64_t k = std::clamp<int64_t>(as_integer(m_.constants[index_id][0]), 0, int64_t(count) - 1);
          if (p.lane_offset.empty()) p.offset += uint32_t(k) * stride;
          else for (uint16_t l : lanes) p.lane_offset[l] += uint32_t(k) * stride;
        } else {
          // An index that varies: every lane gets its own offset. Out-of-range indices are
          // clamped (robust access) rather than read outside the variable.
          if (p.lane_offset.empty()) p.lane_offset.assign(L, p.offset);
          const Src k = src(index_id);
          for (uint16_t l : lanes)
            p.lane_offset[l] += uint32_t(std::clamp<int64_t>(as_integer(k.at(0, l)), 0, int64_t(count) - 1)) * stride;
        }
        type = element;
      }
      pointers_[in.result] = std::move(p);
      return {};
    }
    case Op::OpLoad: {
      const Pointer& p = pointers_[ops[0]];
      const uint32_t var = p.variable;
      const Memory& mem = memory_[var];
      Real* d = dst(in.result);
      const bool relaxed_load =
          precision_ == Precision::half && m_.decorations[var].relaxed && float_valued(m_, in.result_type);
      if (mem.shared) {
        for (uint32_t s = 0; s < n; ++s)
          for (uint16_t l : lanes) {
            const size_t at = size_t(p.at(l)) + s;
            d[s * L + l] = at < mem.slots.size() ? mem.slots[at] : 0.0;
          }
      } else {
        for (uint32_t s = 0; s < n; ++s)
          for (uint16_t l : lanes) {
            const size_t at = (size_t(p.at(l)) + s) * L + l;
            d[s * L + l] = at < mem.slots.size() ? mem.slots[at] : 0.0;
          }
      }
      if (relaxed_load || rounding_[index])
        for (uint32_t s = 0; s < n; ++s)
          for (uint16_t l : lanes) d[s * L + l] = relaxed_load ? Real(round_to_half(double(d[s * L + l]))) : rounded(index, d[s * L + l]);
      return {};
    }
    case Op::OpStore: {
      const Pointer& p = pointers_[ops[0]];
      Memory& mem = memory_[p.variable];
      if (mem.shared) return std::unexpected(error(in, "a store into read-only memory"));
      const Src v = src(ops[1]);
      const uint32_t count = slots_of(ops[1]);
      const bool relaxed_store =
          precision_ == Precision::half && m_.decorations[p.variable].relaxed && float_valued(m_, m_.type_of[ops[1]]);
      for (uint32_t s = 0; s < count; ++s)
        for (uint16_t l : lanes) {
          const size_t at = (size_t(p.at(l)) + s) * L + l;
          if (at < mem.slots.size()) mem.slots[at] = relaxed_store ? Real(round_to_half(double(v.at(s, l)))) : v.at(s, l);
        }
      return {};
    }
    case Op::OpCopyMemory: {
      const Pointer& to = pointers_[ops[0]];
      const Pointer& from = pointers_[ops[1]];
      Memory& target = memory_[to.variable];
      const Memory& source = memory_[from.variable];
      const uint32_t count = m_.types[m_.types[m_.type_of[ops[0]]].element].slots;
      for (uint32_t s = 0; s < count; ++s)
        for (uint16_t l : lanes) {
          const size_t at = (size_t(to.at(l)) + s) * L + l;
          const size_t from_at = source.shared ? size_t(from.at(l)) + s : (size_t(from.at(l)) + s) * L + l;
          if (at < target.slots.size() && from_at < source.slots.size()) target.slots[at] = source.slots[from_at];
        }
      return {};
    }
    case Op::OpCopyObject: case Op::OpCopyLogical: {
      if (rt.kind == K::pointer) {
        pointers_[in.result] = pointers_[ops[0]];
        return {};
      }
      unary([](Real x) { return x; });
      return {};
    }
    case Op::OpUndef: {
      Real* d = dst(in.result);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) d[s * L + l] = 0;
      return {};
    }
    case Op::OpPhi: {
      Real* d = dst(in.result);
      for (uint16_t l : lanes)
        for (size_t i = 0; i + 1 < ops.size(); i += 2)
          if (ops[i + 1] == predecessor_[l]) {
            const Src v = src(ops[i]);
            for (uint32_t s = 0; s < n; ++s) d[s * L + l] = v.at(s, l);
            break;
          }
      return {};
    }
    case Op::OpFunctionCall: return call(in, lanes);
    case Op::OpKill: case Op::OpTerminateInvocation:
      for (uint16_t l : lanes) discarded_[l] = 1;
      lanes.clear();
      return {};
    case Op::OpDemoteToHelperInvocation:
      // The lane goes on as a helper (its derivatives still count) but writes nothing.
      for (uint16_t l : lanes) discarded_[l] = 1;
      return {};

    // Composites.
    case Op::OpCompositeConstruct: {
      Real* d = dst(in.result);
      uint32_t at = 0;
      for (uint32_t part : ops) {
        const Src v = src(part);
        const uint32_t count = slots_of(part);
        for (uint32_t s = 0; s < count && at < n; ++s, ++at)
          for (uint16_t l : lanes) d[at * L + l] = v.at(s, l);
      }
      return {};
    }
    case Op::OpCompositeExtract: case Op::OpCompositeInsert: {
      const bool insert = op == Op::OpCompositeInsert;
      const uint32_t composite = insert ? ops[1] : ops[0];
      uint32_t type = m_.type_of[composite], offset = 0;
      for (size_t i = insert ? 2 : 1; i < ops.size(); ++i) {
        const Type& t = m_.types[type];
        if (t.kind == K::structure) {
          if (ops[i] >= t.members.size()) return std::unexpected(error(in, "member index out of range"));
          offset += t.member_slots[ops[i]];
          type = t.members[ops[i]];
        } else {
          if (t.kind != K::runtime_array && ops[i] >= t.count) return std::unexpected(error(in, "index out of range"));
          offset += ops[i] * m_.types[t.element].slots;
          type = t.element;
        }
      }
      const Src c = src(composite);
      Real* d = dst(in.result);
      if (!insert) {
        for (uint32_t s = 0; s < n; ++s)
          for (uint16_t l : lanes) d[s * L + l] = c.at(offset + s, l);
        return {};
      }
      const Src object = src(ops[0]);
      const uint32_t count = m_.types[type].slots;
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) d[s * L + l] = s >= offset && s < offset + count ? object.at(s - offset, l) : c.at(s, l);
      return {};
    }
    case Op::OpVectorShuffle: {
      const Src a = src(ops[0]), b = src(ops[1]);
      const uint32_t a_count = slots_of(ops[0]);
      Real* d = dst(in.result);
      for (uint32_t s = 0; s < n; ++s) {
        const uint32_t pick = ops[2 + s];
        for (uint16_t l : lanes)
          d[s * L + l] = pick == 0xffffffffu ? 0.0 : pick < a_count ? a.at(pick, l) : b.at(pick - a_count, l);
      }
      return {};
    }
    case Op::OpVectorExtractDynamic: {
      const Src v = src(ops[0]), k = src(ops[1]);
      const int64_t count = slots_of(ops[0]);
      Real* d = dst(in.result);
      for (uint16_t l : lanes) d[l] = v.at(uint32_t(std::clamp<int64_t>(as_integer(k.at(0, l)), 0, count - 1)), l);
      return {};
    }
    case Op::OpVectorInsertDynamic: {
      const Src v = src(ops[0]), c = src(ops[1]), k = src(ops[2]);
      Real* d = dst(in.result);
      for (uint16_t l : lanes) {
        const int64_t at = as_integer(k.at(0, l));
        for (uint32_t s = 0; s < n; ++s) d[s * L + l] = int64_t(s) == at ? c.at(0, l) : v.at(s, l);
      }
      return {};
    }
    case Op::OpTranspose: {
      const Type& column = m_.types[rt.element];
      const uint32_t rows = column.count, cols = rt.count;   // result: cols columns of rows
      const Src a = src(ops[0]);
      Real* d = dst(in.result);
      for (uint32_t c = 0; c < cols; ++c)
        for (uint32_t r = 0; r < rows; ++r)
          for (uint16_t l : lanes) d[(c * rows + r) * L + l] = a.at(r * cols + c, l);
      return {};
    }

    // Float arithmetic.
    case Op::OpFNegate: unary([](Real x) { return -x; }); return {};
    case Op::OpFAdd: binary([](Real x, Real y) { return x + y; }); return {};
    case Op::OpFSub: binary([](Real x, Real y) { return x - y; }); return {};
    case Op::OpFMul: case Op::OpVectorTimesScalar: case Op::OpMatrixTimesScalar:
      binary([](Real x, Real y) { return x * y; });
      return {};
    case Op::OpFDiv: binary([](Real x, Real y) { return x / y; }); return {};
    case Op::OpFRem: binary([](Real x, Real y) { return fmod(x, y); }); return {};
    case Op::OpFMod: binary([](Real x, Real y) { return x - y * floor(x / y); }); return {};
    case Op::OpDot: {
      const Src a = src(ops[0]), b = src(ops[1]);
      const uint32_t count = slots_of(ops[0]);
      Real* d = dst(in.result);
      for (uint16_t l : lanes) {
        Real sum = rounded(index, a.at(0, l) * b.at(0, l));
        for (uint32_t s = 1; s < count; ++s) sum = rounded(index, sum + rounded(index, a.at(s, l) * b.at(s, l)));
        d[l] = sum;
      }
      return {};
    }
    case Op::OpMatrixTimesVector: case Op::OpVectorTimesMatrix: case Op::OpMatrixTimesMatrix: case Op::OpOuterProduct: {
      // result[c][r] = sum_k A[k][r] * B[c][k], each product and sum rounded in order.
      const Src a = src(ops[0]), b = src(ops[1]);
      const Type& at = m_.types[m_.type_of[ops[0]]];
      const Type& bt = m_.types[m_.type_of[ops[1]]];
      Real* d = dst(in.result);
      auto dot_into = [&](uint32_t slot, auto a_at, auto b_at, uint32_t terms) {
        for (uint16_t l : lanes) {
          Real sum = rounded(index, a_at(0u, l) * b_at(0u, l));
          for (uint32_t k = 1; k < terms; ++k) sum = rounded(index, sum + rounded(index, a_at(k, l) * b_at(k, l)));
          d[slot * L + l] = sum;
        }
      };
      if (op == Op::OpMatrixTimesVector) {   // A: cols x rows, b: vector of cols
        const uint32_t rows = m_.types[at.element].count, cols = at.count;
        for (uint32_t r = 0; r < rows; ++r)
          dot_into(r, [&](uint32_t k, uint16_t l) { return a.at(k * rows + r, l); },
                   [&](uint32_t k, uint16_t l) { return b.at(k, l); }, cols);
      } else if (op == Op::OpVectorTimesMatrix) {   // a: vector of rows, B: cols columns of rows
        const uint32_t rows = m_.types[bt.element].count;
        for (uint32_t c = 0; c < bt.count; ++c)
          dot_into(c, [&](uint32_t k, uint16_t l) { return a.at(k, l); },
                   [&](uint32_t k, uint16_t l) { return b.at(c * rows + k, l); }, rows);
      } else if (op == Op::OpMatrixTimesMatrix) {
        const uint32_t rows = m_.types[at.element].count, inner = at.count;
        for (uint32_t c = 0; c < bt.count; ++c)
          for (uint32_t r = 0; r < rows; ++r)
            dot_into(c * rows + r, [&](uint32_t k, uint16_t l) { return a.at(k * rows + r, l); },
                     [&](uint32_t k, uint16_t l) { return b.at(c * inner + k, l); }, inner);
      } else {   // outer product: column c = a * b[c]
        const uint32_t rows = slots_of(ops[0]);
        for (uint32_t c = 0; c < rt.count; ++c)
          for (uint32_t r = 0; r < rows; ++r)
            for (uint16_t l : lanes) d[(c * rows + r) * L + l] = rounded(index, a.at(r, l) * b.at(c, l));
      }
      return {};
    }

    // Integer arithmetic and bits.
    case Op::OpSNegate: {
      const Src a = src(ops[0]);
      Real* d = dst(in.result);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) d[s * L + l] = wrap_integer(scalar_type, wrapping_negate(as_integer(a.at(s, l))));
      return {};
    }
    case Op::OpNot: {
      const Src a = src(ops[0]);
      Real* d = dst(in.result);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) d[s * L + l] = wrap_integer(scalar_type, ~as_integer(a.at(s, l)));
      return {};
    }
    // In uint64: 64-bit operands wrap as the device's do, where int64_t would overflow.
    case Op::OpIAdd: integer_binary([](int64_t x, int64_t y) { return int64_t(uint64_t(x) + uint64_t(y)); }); return {};
    case Op::OpISub: integer_binary([](int64_t x, int64_t y) { return int64_t(uint64_t(x) - uint64_t(y)); }); return {};
    case Op::OpIMul: integer_binary([](int64_t x, int64_t y) { return int64_t(uint64_t(x) * uint64_t(y)); }); return {};
    case Op::OpSDiv: {
      const Src a = src(ops[0]), b = src(ops[1]);
      Real* d = dst(in.result);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) {
          const int64_t x = signed_of(ops[0], a.at(s, l)), y = signed_of(ops[1], b.at(s, l));
          d[s * L + l] = wrap_integer(scalar_type, y == 0 ? 0 : y == -1 ? wrapping_negate(x) : x / y);
        }
      return {};
    }
    case Op::OpUDiv: case Op::OpUMod: {
      const Src a = src(ops[0]), b = src(ops[1]);
      Real* d = dst(in.result);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) {
          const uint64_t x = unsigned_of(ops[0], a.at(s, l)), y = unsigned_of(ops[1], b.at(s, l));
          d[s * L + l] = wrap_integer(scalar_type, int64_t(y == 0 ? 0 : op == Op::OpUDiv ? x / y : x % y));
        }
      return {};
    }
    case Op::OpSRem: case Op::OpSMod: {
      const Src a = src(ops[0]), b = src(ops[1]);
      Real* d = dst(in.result);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) {
          const int64_t x = signed_of(ops[0], a.at(s, l)), y = signed_of(ops[1], b.at(s, l));
          int64_t r = y == 0 || y == -1 ? 0 : x % y;   // INT64_MIN % -1 traps
          if (op == Op::OpSMod && r != 0 && ((r < 0) != (y < 0))) r += y;
          d[s * L + l] = wrap_integer(scalar_type, r);
        }
      return {};
    }
    case Op::OpShiftLeftLogical: case Op::OpShiftRightLogical: case Op::OpShiftRightArithmetic: {
      const Src a = src(ops[0]), b = src(ops[1]);
      const uint32_t width = scalar_type.width;
      Real* d = dst(in.result);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) {
          const uint64_t shift = unsigned_of(ops[1], b.at(s, l)) % width;
          int64_t r;
          if (op == Op::OpShiftLeftLogical) r = int64_t(unsigned_of(ops[0], a.at(s, l)) << shift);
          else if (op == Op::OpShiftRightLogical) r = int64_t(unsigned_of(ops[0], a.at(s, l)) >> shift);
          else r = signed_of(ops[0], a.at(s, l)) >> shift;
          d[s * L + l] = wrap_integer(scalar_type, r);
        }
      return {};
    }
    case Op::OpBitwiseAnd: integer_binary([](int64_t x, int64_t y) { return x & y; }); return {};
    case Op::OpBitwiseOr: integer_binary([](int64_t x, int64_t y) { return x | y; }); return {};
    case Op::OpBitwiseXor: integer_binary([](int64_t x, int64_t y) { return x ^ y; }); return {};

    // Conversions.
    case Op::OpConvertFToS: case Op::OpConvertFToU: {
      const Src a = src(ops[0]);
      Real* d = dst(in.result);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) d[s * L + l] = float_to_integer(scalar_type, a.at(s, l));
      return {};
    }
    case Op::OpConvertSToF: case Op::OpConvertUToF: case Op::OpFConvert:
      unary([](Real x) { return x; });
      return {};
    case Op::OpSConvert: case Op::OpUConvert: {
      const Src a = src(ops[0]);
      Real* d = dst(in.result);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) d[s * L + l] = wrap_integer(scalar_type, as_integer(a.at(s, l)));
      return {};
    }
    case Op::OpQuantizeToF16: unary([](Real x) { return Real(round_to_half(double(x))); }); return {};
    case Op::OpBitcast: {
      const Type& from_type = m_.types[m_.type_of[ops[0]]];
      const Type& from = from_type.kind == K::vector ? m_.types[from_type.element] : from_type;
      if (from.width != scalar_type.width || slots_of(ops[0]) != n)
        return std::unexpected(error(in, "the twin bitcasts only between types of one width and size"));
      const Src a = src(ops[0]);
      Real* d = dst(in.result);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) d[s * L + l] = from_bits(scalar_type, bits_of(from, a.at(s, l)));
      return {};
    }

    // Comparisons and logic.
    case Op::OpFOrdEqual: compare([](Real x, Real y) { return x == y; }); return {};
    case Op::OpFUnordEqual: compare([](Real x, Real y) { return !(x < y || x > y); }); return {};
    case Op::OpFOrdNotEqual: compare([](Real x, Real y) { return x < y || x > y; }); return {};
    case Op::OpFUnordNotEqual: compare([](Real x, Real y) { return !(x == y); }); return {};
    case Op::OpFOrdLessThan: compare([](Real x, Real y) { return x < y; }); return {};
    case Op::OpFUnordLessThan: compare([](Real x, Real y) { return !(x >= y); }); return {};
    case Op::OpFOrdGreaterThan: compare([](Real x, Real y) { return x > y; }); return {};
    case Op::OpFUnordGreaterThan: compare([](Real x, Real y) { return !(x <= y); }); return {};
    case Op::OpFOrdLessThanEqual: compare([](Real x, Real y) { return x <= y; }); return {};
    case Op::OpFUnordLessThanEqual: compare([](Real x, Real y) { return !(x > y); }); return {};
    case Op::OpFOrdGreaterThanEqual: compare([](Real x, Real y) { return x >= y; }); return {};
    case Op::OpFUnordGreaterThanEqual: compare([](Real x, Real y) { return !(x < y); }); return {};
    case Op::OpIEqual: case Op::OpLogicalEqual: compare([](Real x, Real y) { return x == y; }); return {};
    case Op::OpINotEqual: case Op::OpLogicalNotEqual: compare([](Real x, Real y) { return x != y; }); return {};
    case Op::OpSLessThan: case Op::OpULessThan: compare([](Real x, Real y) { return x < y; }); return {};
    case Op::OpSGreaterThan: case Op::OpUGreaterThan: compare([](Real x, Real y) { return x > y; }); return {};
    case Op::OpSLessThanEqual: case Op::OpULessThanEqual: compare([](Real x, Real y) { return x <= y; }); return {};
    case Op::OpSGreaterThanEqual: case Op::OpUGreaterThanEqual:
      compare([](Real x, Real y) { return x >= y; });
      return {};
    case Op::OpLogicalAnd: compare([](Real x, Real y) { return x != 0 && y != 0; }); return {};
    case Op::OpLogicalOr: compare([](Real x, Real y) { return x != 0 || y != 0; }); return {};
    case Op::OpLogicalNot: {
      const Src a = src(ops[0]);
      Real* d = dst(in.result);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) d[s * L + l] = a.at(s, l) == 0 ? 1.0 : 0.0;
      return {};
    }
    case Op::OpIsNan: case Op::OpIsInf: {
      const Src a = src(ops[0]);
      Real* d = dst(in.result);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) d[s * L + l] = op == Op::OpIsNan ? isnan(a.at(s, l)) : isinf(a.at(s, l));
      return {};
    }
    case Op::OpAny: case Op::OpAll: {
      const Src a = src(ops[0]);
      const uint32_t count = slots_of(ops[0]);
      Real* d = dst(in.result);
      for (uint16_t l : lanes) {
        bool any = false, all = true;
        for (uint32_t s = 0; s < count; ++s) {
          any = any || a.at(s, l) != 0;
          all = all && a.at(s, l) != 0;
        }
        d[l] = (op == Op::OpAny ? any : all) ? 1.0 : 0.0;
      }
      return {};
    }
    case Op::OpSelect: {
      const Src c = src(ops[0]), a = src(ops[1]), b = src(ops[2]);
      const bool scalar_condition = slots_of(ops[0]) == 1;
      Real* d = dst(in.result);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) d[s * L + l] = c.at(scalar_condition ? 0 : s, l) != 0 ? a.at(s, l) : b.at(s, l);
      return {};
    }

    // Derivatives: differences within the 2x2 quad, per row (x) and per column (y), as
    // llvmpipe computes them; coarse ones from the quad's first row and column.
    case Op::OpDPdx: case Op::OpDPdy: case Op::OpFwidth: case Op::OpDPdxFine: case Op::OpDPdyFine:
    case Op::OpFwidthFine: case Op::OpDPdxCoarse: case Op::OpDPdyCoarse: case Op::OpFwidthCoarse: {
      const Src a = src(ops[0]);
      Real* d = dst(in.result);
      const bool coarse = op == Op::OpDPdxCoarse || op == Op::OpDPdyCoarse || op == Op::OpFwidthCoarse;
      const bool want_x = op == Op::OpDPdx || op == Op::OpDPdxFine || op == Op::OpDPdxCoarse;
      const bool want_y = op == Op::OpDPdy || op == Op::OpDPdyFine || op == Op::OpDPdyCoarse;
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) {
          if (!quads_) {
            d[s * L + l] = 0;
            continue;
          }
          const uint32_t q = l & ~3u, row = coarse ? 0 : (l & 2u), column = coarse ? 0 : (l & 1u);
          const Real dx = rounded(index, a.at(s, q + row + 1) - a.at(s, q + row));
          const Real dy = rounded(index, a.at(s, q + column + 2) - a.at(s, q + column));
          d[s * L + l] = want_x ? dx : want_y ? dy : rounded(index, fabs(dx) + fabs(dy));
        }
      return {};
    }

    case Op::OpExtInst:
      if (m_.non_semantic[ops[0]]) return {};
      return execute_ext(index, lanes);

    case Op::OpSampledImage: case Op::OpImage: case Op::OpImageSampleImplicitLod: case Op::OpImageSampleExplicitLod:
    case Op::OpImageSampleProjImplicitLod: case Op::OpImageSampleProjExplicitLod: case Op::OpImageFetch:
    case Op::OpImageQuerySize: case Op::OpImageQuerySizeLod: case Op::OpImageQueryLevels: case Op::OpImageQueryLod:
      return execute_image(index, lanes);

    default:
      return std::unexpected(error(in, "the twin does not support " + opcode_name(in.op)));
  }
}

template class BasicExecutor<double>;
template class BasicExecutor<WideReal>;

}  // namespace twin
