#include "compile/CompileCache.h"

#include <cstring>
#include <string_view>

#include "compile/CrossGlsl.h"
#include "compile/ModuleCodec.h"
#include "compile/ShaderFileText.h"
#include "compile/ToolVersions.h"
#include "core/Sha256.h"

namespace shaderbed {
namespace {

// The entry layout; bump the version when it (or the module codec) changes.
constexpr std::string_view kMagic = "shaderbed compile cache\n";
constexpr uint32_t kFormat = 2;   // 2: named and checked by SHA-256, not FNV-1a
constexpr const char* kStageKind = "stage";
constexpr const char* kCrossKind = "cross";

struct ProcessCounts {
  std::atomic<size_t> memory_hits{0}, disk_hits{0}, disk_misses{0}, compiles{0};
};
ProcessCounts& process_counts() {
  static ProcessCounts counts;
  return counts;
}

// Key material: named, length-prefixed fields, so no two different inputs spell the same key.
class Key {
 public:
  Key& field(std::string_view name, std::string_view value) {
    text_.append(name).append(" ").append(std::to_string(value.size())).append(":").append(value).append("\n");
    return *this;
  }
  std::string take() { return std::move(text_); }

 private:
  std::string text_ = "shaderbed compile key 1\n";
};

const char* target_name(Target t) { return t == Target::vulkan ? "vulkan" : "opengl"; }

}  // namespace

const CompileToolchain& current_compile_toolchain() {
  static const CompileToolchain toolchain = [] {
    const CompilerVersions v = compiler_versions();
    return CompileToolchain{v.glslang, v.spirv_tools, v.spirv_cross, compile_stage_fingerprint()};
  }();
  return toolchain;
}

CompileCacheCounts operator-(const CompileCacheCounts& a, const CompileCacheCounts& b) {
  return {a.memory_hits - b.memory_hits, a.disk_hits - b.disk_hits, a.disk_misses - b.disk_misses,
          a.compiles - b.compiles};
}

CompileCacheCounts operator+(const CompileCacheCounts& a, const CompileCacheCounts& b) {
  return {a.memory_hits + b.memory_hits, a.disk_hits + b.disk_hits, a.disk_misses + b.disk_misses,
          a.compiles + b.compiles};
}

CompileCacheCounts compile_cache_counts() {
  const ProcessCounts& c = process_counts();
  return {c.memory_hits.load(), c.disk_hits.load(), c.disk_misses.load(), c.compiles.load()};
}

void count_compile_memory_hit() { ++process_counts().memory_hits; }
void count_compile_run() { ++process_counts().compiles; }

CompileCache::CompileCache(std::filesystem::path dir, CompileToolchain toolchain, bool writes)
    : disk_(std::move(dir)), toolchain_(std::move(toolchain)), writes_(writes) {}

CompileCacheCounts CompileCache::counts() const { return {0, hits_.load(), misses_.load(), compiles_.load()}; }

std::string CompileCache::stage_key(Language language, const ShaderSource& source, Target target) const {
  std::string defines, include_dirs;
  for (const auto& [name, value] : source.defines) defines += name + '=' + value + '\n';
  for (const std::string& dir : source.include_dirs) include_dirs += dir + '\n';
  return Key()
      .field("kind", kStageKind)
      .field("language", to_string(language))
      .field("stage", to_string(source.stage))
      .field("target", target_name(target))
      .field("entry", source.entry_point)
      .field("path", source.path)
      .field("text", source.text)
      .field("defines", defines)
      .field("include-dirs", include_dirs)
      .field("glslang", toolchain_.glslang)
      .field("spirv-tools", toolchain_.spirv_tools)
      .field("spirv-cross", toolchain_.spirv_cross)
      .field("stage-code", toolchain_.stage_code)
      .take();
}

std::string CompileCache::cross_key(const std::vector<uint32_t>& spirv, Stage stage) const {
  return Key()
      .field("kind", kCrossKind)
      .field("stage", to_string(stage))
      .field("spirv", std::string_view(reinterpret_cast<const char*>(spirv.data()), spirv.size() * sizeof(uint32_t)))
      .field("spirv-cross", toolchain_.spirv_cross)
      .field("stage-code", toolchain_.stage_code)
      .take();
}

std::string CompileCache::entry_name(const std::string& key, const char* kind) {
  return sha256_hex(key) + "." + kind;
}

std::optional<std::string> CompileCache::find(const std::string& key, const char* kind) {
  const std::optional<std::string> bytes = disk_.load(entry_name(key, kind));
  if (!bytes || bytes->size() < kMagic.size() + sizeof(Sha256Digest)) return std::nullopt;
  // The stored SHA-256 must be the body's: an entry edited without it is recompiled. (One
  // who can write the folder can write a matching hash too; the cache is the user's own.)
  const std::string_view body(bytes->data(), bytes->size() - sizeof(Sha256Digest));
  const Sha256Digest checksum = sha256(body);
  if (std::memcmp(checksum.data(), bytes->data() + body.size(), checksum.size()) != 0 || !body.starts_with(kMagic))
    return std::nullopt;

  ByteReader in(body.substr(kMagic.size()));
  uint32_t format = 0;
  std::string stored_key;
  if (!in.u32(format) || format != kFormat || !in.str(stored_key) || stored_key != key) return std::nullopt;
  uint64_t files = 0;
  if (!in.u64(files) || files > in.remaining() / 16) return std::nullopt;
  for (uint64_t i = 0; i < files; ++i) {
    SourceFile f;
    if (!in.str(f.path) || !in.str(f.text)) return std::nullopt;
    // Read as the compile read it (ShaderFileText.h), so a file with a BOM can be a hit.
    const Result<std::string> now = read_shader_text(f.path, "#include");
    if (!now || *now != f.text) return std::nullopt;   // an #included file changed (or went)
  }
  std::string payload;
  if (!in.str(payload) || !in.at_end()) return std::nullopt;
  return payload;
}

void CompileCache::store(const std::string& key, const char* kind, const std::vector<SourceFile>& read_files,
                         const std::string& payload) {
  if (!writes_) return;
  ByteWriter out;
  out.u32(kFormat);
  out.str(key);
  out.u64(read_files.size());
  for (const SourceFile& f : read_files) {
    out.str(f.path);
    out.str(f.text);
  }
  out.str(payload);
  std::string entry(kMagic);
  entry += out.bytes();
  const Sha256Digest checksum = sha256(entry);
  entry.append(reinterpret_cast<const char*>(checksum.data()), checksum.size());
  disk_.store(entry_name(key, kind), entry);
}

std::optional<ShaderModule> CompileCache::find_stage(Language language, const ShaderSource& source, Target target) {
  std::optional<ShaderModule> module;
  if (std::optional<std::string> payload = find(stage_key(language, source, target), kStageKind))
    module = decode_module(*payload);
  ++(module ? hits_ : misses_);
  ++(module ? process_counts().disk_hits : process_counts().disk_misses);
  return module;
}

std::optional<std::string> CompileCache::find_cross_glsl(const std::vector<uint32_t>& spirv, Stage stage) {
  std::optional<std::string> glsl = find(cross_key(spirv, stage), kCrossKind);
  ++(glsl ? hits_ : misses_);
  ++(glsl ? process_counts().disk_hits : process_counts().disk_misses);
  return glsl;
}

Result<ShaderModule> CompileCache::stage(Language language, const ShaderSource& source, Target target) {
  if (std::optional<ShaderModule> hit = find_stage(language, source, target)) return std::move(*hit);
  ++compiles_;
  count_compile_run();
  std::vector<SourceFile> read_files;
  Result<ShaderModule> module = compile_stage(language, source, target, &read_files);
  if (module) store(stage_key(language, source, target), kStageKind, read_files, encode_module(*module));
  return module;
}

Result<std::string> CompileCache::cross_glsl(const std::vector<uint32_t>& spirv, Stage stage) {
  if (std::optional<std::string> hit = find_cross_glsl(spirv, stage)) return std::move(*hit);
  ++compiles_;
  count_compile_run();
  Result<std::string> glsl = spirv_to_glsl(spirv, stage);
  if (glsl) store(cross_key(spirv, stage), kCrossKind, {}, *glsl);
  return glsl;
}

}  // namespace shaderbed
