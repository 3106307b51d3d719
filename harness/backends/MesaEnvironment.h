#pragma once

namespace shaderbed {

// Determinism: Mesa's on-disk shader cache (~/.cache/mesa_shader_cache) makes build
// times depend on earlier runs and writes to the user's home. Disable it for this
// process unless the user configured the cache themselves. Call before a driver loads.
void isolate_mesa_shader_cache();

}  // namespace shaderbed
