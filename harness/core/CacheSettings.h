#pragma once
// Where shaderbed keeps what it can reuse between runs, and which caches are on: one
// place the CLI sets (before any driver loads or any shader compiles) and every stage
// reads. Two caches live under the root (docs/caches.md):
//   <root>/mesa      Mesa's own disk shader cache (MESA_SHADER_CACHE_DIR), for the drivers
//   <root>/compile   shaderbed's compile cache: SPIR-V + reflection, SPIRV-Cross GLSL
// Neither can change a result: each is keyed by everything that produces its bytes.
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

}  // namespace shaderbed
