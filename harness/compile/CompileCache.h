#pragma once
// The disk compile cache (<cache root>/compile, docs/caches.md): compile_stage() results
// (SPIR-V + reflection) and SPIRV-Cross GLSL, kept between processes so a warm run starts
// no compiler at all.
//
// A stage entry is keyed by everything that affects its bytes: language, stage, target,
// entry point, source path and exact text, the versions of glslang, SPIRV-Tools and
// SPIRV-Cross, and a fingerprint of shaderbed's own compile stage (its sources and the
// compiler libraries it links, hashed at build time). The SHA-256 of that key is only the
// file name: the entry stores the whole key and a hit compares it byte for byte, so a
// collision cannot serve another shader's SPIR-V. Files the compile #included are stored
// with their paths and exact contents, and a hit re-reads each one: any change is a miss
// (ccache's manifest idea). A cross entry is keyed by the SPIR-V words, the stage and the
// same versions and fingerprint.
//
// Only successful compiles are stored. An entry ends with the SHA-256 of the rest: one
// that is missing, truncated, corrupt or edited (the hash does not match), of another
// format or of another key is a miss, never an error.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "compile/Compiler.h"
#include "compile/DiskCache.h"

namespace shaderbed {

// What, besides the inputs, decides a compile's output bytes.
struct CompileToolchain {
  std::string glslang, spirv_tools, spirv_cross;   // compiler_versions()
  std::string stage_code;                          // compile_stage_fingerprint()
};
// This build's (computed once; starts no compiler).
const CompileToolchain& current_compile_toolchain();

// Cache use, counted per lookup. hits() are requests answered without running a
// compiler (from this process's memory or from disk); misses() are the requests that ran
// one (glslang + SPIRV-Tools for a stage, SPIRV-Cross for a cross compile).
struct CompileCacheCounts {
  size_t memory_hits = 0;
  size_t disk_hits = 0;
  size_t disk_misses = 0;   // looked up on disk, not usable there
  size_t compiles = 0;      // a compiler ran
  size_t hits() const { return memory_hits + disk_hits; }
  size_t misses() const { return compiles; }
};
CompileCacheCounts operator-(const CompileCacheCounts& a, const CompileCacheCounts& b);
CompileCacheCounts operator+(const CompileCacheCounts& a, const CompileCacheCounts& b);   // two processes' counts

// The process's counts, every cache instance and layer together (what run reports).
CompileCacheCounts compile_cache_counts();
// Called by the in-memory layer (StageCache.cpp).
void count_compile_memory_hit();
void count_compile_run();

class CompileCache {
 public:
  // With `writes` false the cache is only read (a full or unwritable folder).
  explicit CompileCache(std::filesystem::path dir, CompileToolchain toolchain = current_compile_toolchain(),
                        bool writes = true);
  const std::filesystem::path& dir() const { return disk_.dir(); }

  // From the cache, else compile_stage(), storing a success.
  Result<ShaderModule> stage(Language language, const ShaderSource& source, Target target);
  // From the cache, else spirv_to_glsl() (CrossGlsl.h), storing a success.
  Result<std::string> cross_glsl(const std::vector<uint32_t>& spirv, Stage stage);

  // Lookups alone (counted as hits or disk misses).
  std::optional<ShaderModule> find_stage(Language language, const ShaderSource& source, Target target);
  std::optional<std::string> find_cross_glsl(const std::vector<uint32_t>& spirv, Stage stage);

  // This instance's counts (memory_hits stays 0: the memory layer is StageCache's).
  CompileCacheCounts counts() const;

  // The key material, exactly as stored and compared (tests, debugging).
  std::string stage_key(Language language, const ShaderSource& source, Target target) const;
  std::string cross_key(const std::vector<uint32_t>& spirv, Stage stage) const;
  // The entry file a key is stored in, relative to dir().
  static std::string entry_name(const std::string& key, const char* kind);

 private:
  std::optional<std::string> find(const std::string& key, const char* kind);
  void store(const std::string& key, const char* kind, const std::vector<SourceFile>& read_files,
             const std::string& payload);

  DiskCache disk_;
  CompileToolchain toolchain_;
  bool writes_ = true;
  std::atomic<size_t> hits_{0}, misses_{0}, compiles_{0};
};

}  // namespace shaderbed
