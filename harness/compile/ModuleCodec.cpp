#include "compile/ModuleCodec.h"

#include <cstring>

namespace shaderbed {

// Every field of the reflection is written and read below. A field added to
// ShaderModule.h without a line here would come back from a cache hit as its default:
// these sizes make that a compile error instead (update both functions, then the size).
#if defined(__GLIBCXX__) && defined(__x86_64__)
static_assert(sizeof(UniformMember) == 72, "UniformMember changed: update ModuleCodec.cpp");
static_assert(sizeof(UniformBlock) == 72, "UniformBlock changed: update ModuleCodec.cpp");
static_assert(sizeof(StageInput) == 80, "StageInput changed: update ModuleCodec.cpp");
static_assert(sizeof(SamplerBinding) == 88, "SamplerBinding changed: update ModuleCodec.cpp");
static_assert(sizeof(Reflection) == 72, "Reflection changed: update ModuleCodec.cpp");
static_assert(sizeof(ShaderModule) == 168, "ShaderModule changed: update ModuleCodec.cpp");
#endif

void ByteWriter::u32(uint32_t v) { out_.append(reinterpret_cast<const char*>(&v), sizeof v); }
void ByteWriter::u64(uint64_t v) { out_.append(reinterpret_cast<const char*>(&v), sizeof v); }
void ByteWriter::str(std::string_view s) {
  u64(s.size());
  out_.append(s);
}
void ByteWriter::words(const std::vector<uint32_t>& w) {
  u64(w.size());
  out_.append(reinterpret_cast<const char*>(w.data()), w.size() * sizeof(uint32_t));
}

bool ByteReader::take(void* dst, size_t n) {
  if (!ok_ || in_.size() < n) return ok_ = false;
  std::memcpy(dst, in_.data(), n);
  in_.remove_prefix(n);
  return true;
}
bool ByteReader::u32(uint32_t& v) { return take(&v, sizeof v); }
bool ByteReader::u64(uint64_t& v) { return take(&v, sizeof v); }
bool ByteReader::boolean(bool& v) {
  uint32_t x = 0;
  if (!u32(x) || x > 1) return ok_ = false;
  v = x == 1;
  return true;
}
bool ByteReader::str(std::string& s) {
  uint64_t n = 0;
  if (!u64(n) || n > in_.size()) return ok_ = false;
  s.assign(in_.data(), n);
  in_.remove_prefix(n);
  return true;
}
bool ByteReader::words(std::vector<uint32_t>& w) {
  uint64_t n = 0;
  if (!u64(n) || n > in_.size() / sizeof(uint32_t)) return ok_ = false;
  w.resize(n);
  return take(w.data(), n * sizeof(uint32_t));
}

namespace {

// An element count, checked against what is left so a garbled count cannot ask for a huge
// allocation: every element below takes at least 8 bytes.
bool count(ByteReader& in, uint64_t& n) { return in.u64(n) && n <= in.remaining() / 8; }

}  // namespace

void write_module(ByteWriter& out, const ShaderModule& m) {
  out.u32(uint32_t(m.stage));
  out.str(m.source_file);
  out.str(m.entry_point);
  out.words(m.spirv);
  const Reflection& r = m.reflection;
  out.u64(r.uniform_blocks.size());
  for (const UniformBlock& b : r.uniform_blocks) {
    out.str(b.name);
    out.u32(b.set);
    out.u32(b.binding);
    out.u32(b.size);
    out.u64(b.members.size());
    for (const UniformMember& x : b.members) {
      out.str(x.name);
      out.u32(x.offset);
      out.u32(x.size);
      out.boolean(x.is_float);
      out.u32(x.vecsize);
      out.u32(x.columns);
      out.u32(x.matrix_stride);
      out.boolean(x.column_registers);
      out.u32(x.array_size);
      out.u32(x.array_stride);
      out.boolean(x.read);
    }
  }
  out.u64(r.inputs.size());
  for (const StageInput& x : r.inputs) {
    out.u32(x.location);
    out.str(x.name);
    out.str(x.semantic);
    out.u32(x.components);
  }
  out.u64(r.samplers.size());
  for (const SamplerBinding& x : r.samplers) {
    out.str(x.name);
    out.u32(x.set);
    out.u32(x.binding);
    out.u32(x.dimensions);
    out.u32(uint32_t(x.kind));
    out.boolean(x.cube);
    out.u64(x.paired.size());
    for (const std::string& p : x.paired) out.str(p);
    out.boolean(x.read);
  }
}

bool read_module(ByteReader& in, ShaderModule& m) {
  uint32_t stage = 0;
  if (!in.u32(stage) || stage > uint32_t(Stage::fragment)) return false;
  m.stage = Stage(stage);
  if (!in.str(m.source_file) || !in.str(m.entry_point) || !in.words(m.spirv)) return false;
  Reflection& r = m.reflection;
  uint64_t n = 0;
  if (!count(in, n)) return false;
  r.uniform_blocks.resize(n);
  for (UniformBlock& b : r.uniform_blocks) {
    uint64_t members = 0;
    if (!in.str(b.name) || !in.u32(b.set) || !in.u32(b.binding) || !in.u32(b.size) || !count(in, members))
      return false;
    b.members.resize(members);
    for (UniformMember& x : b.members)
      if (!in.str(x.name) || !in.u32(x.offset) || !in.u32(x.size) || !in.boolean(x.is_float) || !in.u32(x.vecsize) ||
          !in.u32(x.columns) || !in.u32(x.matrix_stride) || !in.boolean(x.column_registers) ||
          !in.u32(x.array_size) || !in.u32(x.array_stride) || !in.boolean(x.read))
        return false;
  }
  if (!count(in, n)) return false;
  r.inputs.resize(n);
  for (StageInput& x : r.inputs)
    if (!in.u32(x.location) || !in.str(x.name) || !in.str(x.semantic) || !in.u32(x.components)) return false;
  if (!count(in, n)) return false;
  r.samplers.resize(n);
  for (SamplerBinding& x : r.samplers) {
    uint32_t kind = 0;
    uint64_t paired = 0;
    if (!in.str(x.name) || !in.u32(x.set) || !in.u32(x.binding) || !in.u32(x.dimensions) || !in.u32(kind) ||
        kind > uint32_t(SamplerKind::sampler) || !in.boolean(x.cube) || !count(in, paired))
      return false;
    x.kind = SamplerKind(kind);
    x.paired.resize(paired);
    for (std::string& p : x.paired)
      if (!in.str(p)) return false;
    if (!in.boolean(x.read)) return false;
  }
  return in.ok();
}

std::string encode_module(const ShaderModule& module) {
  ByteWriter out;
  write_module(out, module);
  return out.take();
}

std::optional<ShaderModule> decode_module(std::string_view bytes) {
  ByteReader in(bytes);
  ShaderModule m;
  if (!read_module(in, m) || !in.at_end()) return std::nullopt;
  return m;
}

}  // namespace shaderbed
