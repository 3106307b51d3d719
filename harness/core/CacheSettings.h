#pragma once
// Where shaderbed keeps what it can reuse between runs, and which caches are on: one
// place the CLI sets (before any driver loads or any shader compiles) and every stage
// reads. Two caches live under the root (docs/caches.md):
//   <root>/mesa      Mesa's own disk shader cache (MESA_SHADER_CACHE_DIR), for the drivers
//   <root>/compile   shaderbed's compile cache: SPIR-V + reflection, SPIRV-Cross GLSL
// Neither can change a result: each is keyed by everything that produces its bytes.
#include <cstdint>
#include <string>

namespace shaderbed {

struct CacheSettings {
  std::string root;     // "" = no folder could be found: both disk caches off
  bool driver = true;   // Mesa's disk shader cache
  bool compile = true;  // shaderbed's disk compile cache

  std::string driver_dir() const;   // <root>/mesa, "" without a root
  std::string compile_dir() const;  // <root>/compile, "" without a root
  bool driver_enabled() const { return driver && !root.empty(); }
  bool compile_enabled() const { return compile && !root.empty(); }
};

// The root from the environment: $SHADERBED_CACHE_DIR, else $XDG_CACHE_HOME/shaderbed,
// else $HOME/.cache/shaderbed (empty variables count as unset); both caches on.
CacheSettings cache_settings_from_environment();

// The process-wide settings. Until set_cache_settings is called they are
// cache_settings_from_environment() (read on first use). Thread-safe.
CacheSettings cache_settings();
void set_cache_settings(CacheSettings settings);

// A cache folder on a full disk is worse than none: Mesa maps its index file, and a page
// it cannot back ends the process with SIGBUS. Below this much free space the caches'
// writes are off.
constexpr uint64_t kCacheMinFreeBytes = uint64_t(16) << 20;

// Why `dir` cannot take the caches' writes: it cannot be created, its filesystem has less
// than `min_free_bytes` free, or a probe write of a few hundred KiB fails (permissions, a
// read-only mount, quota). "" when it can. Creates the folder.
std::string cache_folder_problem(const std::string& dir, uint64_t min_free_bytes = kCacheMinFreeBytes);

// Whether the current settings' root can take writes (cache_folder_problem, decided once
// per root and process). When it cannot, Mesa's cache is disabled and the compile cache
// only read, and one note says so on stderr, once for a process and the shaderbed
// processes it starts.
bool cache_root_writable();

}  // namespace shaderbed
