#include "backends/MesaEnvironment.h"

#include <cstdlib>

namespace shaderbed {

void isolate_mesa_shader_cache() {
  if (std::getenv("MESA_SHADER_CACHE_DISABLE") == nullptr && std::getenv("MESA_SHADER_CACHE_DIR") == nullptr)
    ::setenv("MESA_SHADER_CACHE_DISABLE", "true", /*overwrite=*/0);
}

}  // namespace shaderbed
