#include "pipeline/SpirvWords.h"

namespace shaderbed {

static_assert(std::forward_iterator<SpirvInstructionIterator>);
static_assert(std::sentinel_for<std::default_sentinel_t, SpirvInstructionIterator>);

std::string spirv_literal_string(std::span<const uint32_t> words) {
  std::string s;
  for (const uint32_t word : words)
    for (int byte = 0; byte < 4; ++byte) {
      const char c = static_cast<char>((word >> (8 * byte)) & 0xff);
      if (c == 0) return s;
      s += c;
    }
  return s;
}

}  // namespace shaderbed
