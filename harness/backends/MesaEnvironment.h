#pragma once
#include <string>

namespace shaderbed {

// Mesa's disk shader cache, set up for this process from the cache settings
// (core/CacheSettings.h). Call before a driver loads: lavapipe and llvmpipe read
// MESA_SHADER_CACHE_DIR / MESA_SHADER_CACHE_DISABLE once, when the driver loads.
//
// On by default, in a folder of shaderbed's own (<cache root>/mesa), never the user's
// ~/.cache/mesa_shader_cache. It cannot change a result: Mesa keys every entry by the
// driver's build (the build-id of the driver library) and by a hash of the shader and
// of the compiler options, so a hit is the code the same driver would have generated;
// the whole default suite, warm against cold, gave bit-identical metrics and images.
// What it changes is time: pipeline/program build ("build" in the results) and the
// suite's wall time (9.7 s cold, 3.7 s warm). docs/caches.md has the details.
//
// Precedence: --no-driver-cache (settings.driver == false) sets
// MESA_SHADER_CACHE_DISABLE=true; otherwise a MESA_SHADER_CACHE_DIR or
// MESA_SHADER_CACHE_DISABLE the user set is left alone; otherwise the cache goes to
// <root>/mesa (and is disabled when there is no root, or when the root's folder is full
// or unwritable: cache_root_writable() in core/CacheSettings.h). Values a shaderbed parent process
// set (inherited by a child shaderbed) are not the user's: the child applies its own.
void isolate_mesa_shader_cache();

// What Mesa will use, read from this process's environment (Mesa's own rules).
struct MesaShaderCacheState {
  bool enabled = true;
  std::string dir;   // the folder MESA_SHADER_CACHE_DIR names, or Mesa's default; "" when disabled
};
MesaShaderCacheState mesa_shader_cache_state();

}  // namespace shaderbed
