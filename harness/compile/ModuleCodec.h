#pragma once
// A ShaderModule as bytes and back, for the disk compile cache (CompileCache.h). A plain
// binary form: fixed-width native integers, length-prefixed strings and arrays. Every
// read is bounds-checked, so truncated or garbled input decodes to nothing rather than to
// a wrong module; the cache adds a checksum over the whole entry on top.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compile/ShaderModule.h"

namespace shaderbed {

class ByteWriter {
 public:
  void u32(uint32_t v);
  void u64(uint64_t v);
  void boolean(bool v) { u32(v ? 1 : 0); }
  void str(std::string_view s);                  // u64 length, then the bytes
  void words(const std::vector<uint32_t>& w);    // u64 count, then the words
  const std::string& bytes() const { return out_; }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

// Each read returns false (and leaves the reader failed) when the input is too short.
class ByteReader {
 public:
  explicit ByteReader(std::string_view in) : in_(in) {}
  bool u32(uint32_t& v);
  bool u64(uint64_t& v);
  bool boolean(bool& v);
  bool str(std::string& s);
  bool words(std::vector<uint32_t>& w);
  bool at_end() const { return ok_ && in_.empty(); }
  bool ok() const { return ok_; }
  size_t remaining() const { return in_.size(); }

 private:
  bool take(void* dst, size_t n);
  std::string_view in_;
  bool ok_ = true;
};

void write_module(ByteWriter& out, const ShaderModule& module);
bool read_module(ByteReader& in, ShaderModule& module);

std::string encode_module(const ShaderModule& module);
std::optional<ShaderModule> decode_module(std::string_view bytes);   // nullopt: not a whole module

}  // namespace shaderbed
