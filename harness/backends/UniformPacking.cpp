#include "backends/UniformPacking.h"

#include <cstring>
#include <string>

namespace shaderbed {
namespace {

void write_scalar(std::vector<std::byte>& out, size_t offset, double value, bool is_float) {
  const auto v = float(value);   // the device stores 32-bit floats
  if (offset + 4 > out.size()) return;
  if (is_float) {
    std::memcpy(out.data() + offset, &v, 4);
  } else {
    int32_t i = static_cast<int32_t>(v);
    std::memcpy(out.data() + offset, &i, 4);
  }
}

// Every member resolved and placed at its offset: write(byte offset, value, is_float).
template <typename Write>
Result<void> place_members(const UniformBlock& block, const UniformResolver& resolver, Write write) {
  for (const UniformMember& m : block.members) {
    auto value = resolver.value(block, m);
    if (!value) return std::unexpected(value.error());
    const std::vector<double>& v = *value;
    const uint32_t elements = m.array_size ? m.array_size : 1;
    const uint32_t per_element = m.vecsize * m.columns;
    // A plain vector may be given more components than it has (a float3 bound to a w = 1
    // position); arrays and matrices need every value.
    const size_t needed = m.array_size == 0 && m.columns == 1 ? m.vecsize : size_t(per_element) * elements;
    if (v.size() < needed) {
      return fail(ErrorStage::bind, "uniform '" + m.name + "' needs " + std::to_string(needed) +
                              " values, the binding supplies " + std::to_string(v.size()));
    }
    for (uint32_t e = 0; e < elements; ++e) {
      const size_t base = m.offset + size_t(e) * m.array_stride;
      const double* src = v.data() + size_t(e) * per_element;
      if (m.columns == 1) {
        for (uint32_t c = 0; c < m.vecsize; ++c) write(base + c * 4, src[c], m.is_float);
        continue;
      }
      // Matrix: src is column-major M (src[col * rows + row]).
      const uint32_t rows = m.vecsize, cols = m.columns;
      for (uint32_t col = 0; col < cols; ++col)
        for (uint32_t row = 0; row < rows; ++row) {
          const size_t at = m.column_registers ? base + col * m.matrix_stride + row * 4
                                               : base + row * m.matrix_stride + col * 4;
          write(at, src[col * rows + row], m.is_float);
        }
    }
  }
  return {};
}

}  // namespace

Result<std::vector<std::byte>> pack_uniform_block(const UniformBlock& block, const UniformResolver& resolver) {
  std::vector<std::byte> bytes(block.size, std::byte{0});
  auto placed = place_members(block, resolver, [&](size_t offset, double value, bool is_float) {
    write_scalar(bytes, offset, value, is_float);
  });
  if (!placed) return std::unexpected(placed.error());
  return bytes;
}

Result<std::vector<double>> uniform_block_values(const UniformBlock& block, const UniformResolver& resolver) {
  std::vector<double> words(block.size / 4, 0.0);
  auto placed = place_members(block, resolver, [&](size_t offset, double value, bool is_float) {
    if (offset / 4 < words.size()) words[offset / 4] = is_float ? value : double(int32_t(value));
  });
  if (!placed) return std::unexpected(placed.error());
  return words;
}

}  // namespace shaderbed
