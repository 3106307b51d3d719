#pragma once
// A SPIR-V module read instruction by instruction, opcodes as the official header's spv::Op,
// for the places that read a module's words themselves (names, decorations, entry points)
// instead of going through SPIRV-Cross or SPIRV-Tools:
//
//   for (const SpirvInstruction in : SpirvInstructions(module))
//     if (in.opcode == spv::Op::OpDecorate && in.words.size() >= 4 &&
//         in.words[2] == std::to_underlying(spv::Decoration::Location)) ...
//
// spirv.hpp11 and the spirv.hpp that SPIRV-Cross and glslang ship share one include guard
// (spirv_HPP) and the namespace spv, so a translation unit gets whichever comes first. A file
// that includes this header therefore includes no SPIRV-Cross or glslang SPIRV header, and in
// a folder that has such files it is built outside the unity batches (harness/CMakeLists.txt).
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <span>
#include <string>
#include <utility>  // std::to_underlying: an enumerant as the operand word that encodes it

#include <spirv/unified1/spirv.hpp11>

namespace shaderbed {

// Words before the first instruction: magic, version, generator, id bound, schema.
inline constexpr size_t kSpirvHeaderWords = 5;

struct SpirvInstruction {
  spv::Op opcode{};
  // The whole instruction, numbered as the specification numbers it: words[0] holds the word
  // count and the opcode, words[1] the first operand.
  std::span<const uint32_t> words;
  size_t offset = 0;  // index of words[0] in the module, for callers that patch an operand
};

// Ends at the end of the module or before the first instruction whose word count is 0 or runs
// past the end (a truncated or corrupt module): every word it yields lies inside the module,
// and a zero count cannot loop forever.
class SpirvInstructionIterator {
 public:
  using iterator_concept = std::forward_iterator_tag;
  using value_type = SpirvInstruction;
  using difference_type = std::ptrdiff_t;

  SpirvInstructionIterator() = default;
  SpirvInstructionIterator(std::span<const uint32_t> module, size_t at) : module_(module), at_(at) {
    stop_if_malformed();
  }

  SpirvInstruction operator*() const {
    return {spv::Op(module_[at_] & spv::OpCodeMask), module_.subspan(at_, module_[at_] >> spv::WordCountShift), at_};
  }
  SpirvInstructionIterator& operator++() {
    at_ += module_[at_] >> spv::WordCountShift;
    stop_if_malformed();
    return *this;
  }
  SpirvInstructionIterator operator++(int) {
    SpirvInstructionIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const SpirvInstructionIterator& other) const { return at_ == other.at_; }
  bool operator==(std::default_sentinel_t) const { return at_ == module_.size(); }

 private:
  void stop_if_malformed() {
    if (at_ >= module_.size()) {
      at_ = module_.size();
      return;
    }
    const size_t count = module_[at_] >> spv::WordCountShift;
    if (count == 0 || count > module_.size() - at_) at_ = module_.size();
  }

  std::span<const uint32_t> module_;
  size_t at_ = 0;
};

// The instructions after the header; a module shorter than the header has none.
class SpirvInstructions {
 public:
  explicit SpirvInstructions(std::span<const uint32_t> module) : module_(module) {}
  SpirvInstructionIterator begin() const { return {module_, kSpirvHeaderWords}; }
  std::default_sentinel_t end() const { return {}; }

 private:
  std::span<const uint32_t> module_;
};

// A literal string operand (its words up to the instruction's end): UTF-8 packed from each
// word's lowest byte, ending at the first nul or, in a malformed module, at the last word.
std::string spirv_literal_string(std::span<const uint32_t> words);

}  // namespace shaderbed
