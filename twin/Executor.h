#pragma once
// Executes one stage of a decoded module over a batch of invocations at once: one
// dispatch per instruction for the whole batch, the arithmetic in loops over its lanes.
// Control flow follows the module's structure: at a branch the lanes split by target and
// meet again at the merge block, so a batch stays together wherever its lanes agree. In
// the fragment stage lanes come in 2x2 quads (lane 4q + 0..3 = top-left, top-right,
// bottom-left, bottom-right), which derivatives and implicit-LOD sampling read as GPUs do.
#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <utility>
#include <vector>

#include "twin/Error.h"
#include "twin/Module.h"
#include "twin/Precision.h"
#include "twin/TextureSampling.h"
#include "twin/WideReal.h"

namespace twin {

// What a draw binds, shared by every batch of both stages: uniform and push-constant
// blocks decoded to slots, and the textures and sampler states.
struct BoundResources {
  struct Resource {
    const TextureImage* image = nullptr;   // null: a sampler state alone
    SamplerState sampler;
  };
  std::vector<Resource> resources;                          // a handle is an index here
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> handles;   // (set, binding) -> resource
  // A block's bytes as the device reads them and, when the binder has them, the values its
  // 32-bit words hold before rounding (one double per word): float members read these.
  struct Buffer {
    std::span<const std::byte> bytes;
    std::span<const double> words;
  };
  std::map<std::pair<uint32_t, uint32_t>, Buffer> buffers;   // (set, binding)
  Buffer push_constants;
};

// Sees every value an observed lane computes (the NaN search, the pixel debugger).
class Observer {
 public:
  virtual ~Observer() = default;
  // `instruction` is an index into Module::instructions; `values` its result's slots.
  virtual void value(uint32_t instruction, std::span<const double> values) = 0;
};

// How much one batch may do before run() gives up on it, in the blocks' costs (Block::cost:
// one per instruction and operand plus the values it reads and writes): the loop cap alone
// does not stop nested loops. The library's shaders need under 2^10 per batch, a loop of
// 40 texture reads 2^13, a 1000-step loop of 100 values some 2^17. 2^28 is what the loop
// cap let a small loop run; an endless loop stops after 4 to 7 s of one core (-O2).
constexpr uint64_t default_work_limit = uint64_t{1} << 28;

template <typename Real>
class BasicExecutor {
 public:
  BasicExecutor(const Module& module, const BoundResources& resources, Precision precision);
  void limit_work(uint64_t limit) { work_limit_ = limit; }

  // A new batch of `lanes` invocations; quads: lanes form 2x2 quads (fragment stage).
  // Input variables are then filled through input(), outputs read through output().
  TwinResult<void> begin(uint32_t lanes, bool quads);
  // Slots of an Input variable for the batch: slot s of lane l at [s * lanes + l].
  Real* input(uint32_t variable);
  const Real* output(uint32_t variable) const;
  TwinResult<void> run();
  // Lanes that executed OpKill / OpTerminateInvocation / OpDemoteToHelperInvocation.
  bool discarded(uint32_t lane) const { return discarded_[lane] != 0; }
  // Report every value `lane` computes to `observer` (null: none).
  void observe(Observer* observer, uint32_t lane) {
    observer_ = observer;
    observed_lane_ = lane;
  }
  const Module& module() const { return m_; }

 private:
  using Lanes = std::vector<uint16_t>;
  struct Arrivals {
    std::vector<std::pair<uint32_t, Lanes>> at;   // stop label -> lanes that reached it
    Lanes returned;
    Lanes take(uint32_t label);
    void add(uint32_t label, const Lanes& lanes);
  };
  struct Pointer {
    uint32_t variable = 0;
    uint32_t offset = 0;                 // in slots, when every lane points alike
    std::vector<uint32_t> lane_offset;   // per lane, when an index varied (else empty)
    uint32_t at(uint32_t lane) const { return lane_offset.empty() ? offset : lane_offset[lane]; }
  };
  struct Memory {
    std::vector<Real> slots;   // slot s of lane l at [s * lanes + l]; shared memory has lanes 1
    uint32_t lanes = 1;
    bool shared = false;         // uniform, push-constant or handle memory: one copy for every lane
  };
  struct Src {
    const Real* p;
    size_t slot_stride, lane_stride;
    Real at(uint32_t slot, uint32_t lane) const { return p[slot * slot_stride + lane * lane_stride]; }
  };

  TwinResult<void> run_region(const Function& f, uint32_t label, Lanes lanes, const std::vector<uint32_t>& stops,
                              Arrivals& out);
  TwinResult<void> run_loop(const Function& f, const Block& header, std::vector<std::pair<uint32_t, Lanes>> targets,
                            const std::vector<uint32_t>& stops, Arrivals& out, Lanes& exits);
  TwinResult<void> run_block_body(const Block& block, Lanes& lanes);
  std::vector<std::pair<uint32_t, Lanes>> branch_targets(const Block& block, const Lanes& lanes);
  TwinResult<void> execute(uint32_t index, Lanes& lanes);
  TwinResult<void> execute_op(uint32_t index, Lanes& lanes);
  TwinResult<void> execute_ext(uint32_t index, const Lanes& lanes);     // GLSL.std.450 (Std450.cpp)
  TwinResult<void> execute_image(uint32_t index, const Lanes& lanes);   // images (ImageInstructions.cpp)
  TwinResult<void> call(const Instruction& in, Lanes& lanes);
  TwinError error(const Instruction& in, const std::string& message) const;

  Src src(uint32_t id) const;
  Real* dst(uint32_t id) { return &registers_[register_base_[id]]; }
  uint32_t slots_of(uint32_t id) const { return m_.types[m_.type_of[id]].slots; }
  Real rounded(uint32_t instruction, Real x) const {
    const uint8_t kind = rounding_[instruction];
    return kind == 0 ? x : kind == 1 ? Real(round_to_float(double(x))) : Real(round_to_half(double(x)));
  }
  Memory& memory_of(uint32_t variable) { return memory_[variable]; }
  void observe_result(uint32_t index, const Lanes& lanes);

  const Module& m_;
  const BoundResources& resources_;
  Precision precision_;
  uint32_t lanes_ = 0;
  bool quads_ = false;
  std::vector<uint32_t> register_slot_;   // by id: where its slots start, per lane
  std::vector<uint32_t> register_base_;   // by id: register_slot_ * the batch's lanes
  uint32_t based_lanes_ = 1;              // the lanes register_base_ is scaled for
  std::vector<Real> registers_;
  std::vector<std::vector<Real>> constants_;   // Module::constants in this executor's type
  std::vector<Pointer> pointers_;         // by id
  std::vector<Memory> memory_;            // by variable id
  std::vector<uint8_t> rounding_;         // by instruction: 0 none, 1 binary32, 2 binary16
  std::vector<uint32_t> predecessor_;     // by lane: the block it came from
  std::vector<uint8_t> discarded_;
  std::vector<uint32_t> call_results_;   // the OpFunctionCall results being computed, innermost last
  Observer* observer_ = nullptr;
  uint32_t observed_lane_ = 0;
  uint32_t register_slots_ = 0;           // per lane, over every register
  uint64_t work_limit_ = default_work_limit;
  uint64_t work_ = 0;                     // this batch's, so far
};

// The twin in double (float and half round their results), and in WideReal (WideReal.h)
// to check the double twin itself at chosen pixels.
using Executor = BasicExecutor<double>;
using WideExecutor = BasicExecutor<WideReal>;
extern template class BasicExecutor<double>;
extern template class BasicExecutor<WideReal>;

}  // namespace twin
