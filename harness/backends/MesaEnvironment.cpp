#include "backends/MesaEnvironment.h"

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string_view>

#include "core/CacheSettings.h"

namespace shaderbed {
namespace {

constexpr const char* kDir = "MESA_SHADER_CACHE_DIR";
constexpr const char* kDisable = "MESA_SHADER_CACHE_DISABLE";
// What shaderbed itself put into the environment ("DIR=<path>" or "DISABLE=true"), so a
// child shaderbed can tell an inherited value of ours from one the user set.
constexpr const char* kMarker = "SHADERBED_MESA_SHADER_CACHE";

std::optional<std::string> env(const char* name) {
  const char* v = std::getenv(name);
  if (v == nullptr) return std::nullopt;
  return std::string(v);
}

// Mesa's env_var_as_boolean.
std::optional<bool> as_boolean(const std::optional<std::string>& v) {
  if (!v) return std::nullopt;
  if (*v == "1" || *v == "true" || *v == "y" || *v == "yes") return true;
  if (*v == "0" || *v == "false" || *v == "n" || *v == "no") return false;
  return std::nullopt;
}

// The user's own Mesa cache settings (the deprecated MESA_GLSL_CACHE_* included), not
// counting values an ancestor shaderbed set.
bool user_configured() {
  const std::optional<std::string> marker = env(kMarker);
  const std::optional<std::string> dir = env(kDir), disable = env(kDisable);
  const bool ours = marker && ((dir && !disable && *marker == "DIR=" + *dir) ||
                               (disable && !dir && *marker == "DISABLE=" + *disable));
  if (ours) return false;
  return dir || disable || env("MESA_GLSL_CACHE_DIR") || env("MESA_GLSL_CACHE_DISABLE");
}

// Idempotent: once the environment says what we want, it is not written again (other
// threads may be reading it while a driver loads).
void use_dir(const std::string& dir) {
  if (env(kDir) == dir && !env(kDisable) && env(kMarker) == "DIR=" + dir) return;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);   // Mesa creates only the last level itself
  ::unsetenv(kDisable);
  ::setenv(kDir, dir.c_str(), /*overwrite=*/1);
  ::setenv(kMarker, ("DIR=" + dir).c_str(), 1);
}

void disable() {
  if (env(kDisable) == "true" && !env(kDir) && env(kMarker) == "DISABLE=true") return;
  ::unsetenv(kDir);
  ::setenv(kDisable, "true", /*overwrite=*/1);
  ::setenv(kMarker, "DISABLE=true", 1);
}

}  // namespace

void isolate_mesa_shader_cache() {
  // Backends call this from their constructors, possibly on several worker threads at
  // once; setenv must not race with itself.
  static std::mutex mutex;
  const std::lock_guard lock(mutex);
  const CacheSettings settings = cache_settings();
  if (!settings.driver) {
    disable();
    return;
  }
  if (user_configured()) return;
  if (!settings.driver_enabled()) {   // no cache folder at all: never fall back to ~/.cache
    disable();
    return;
  }
  if (!cache_root_writable()) {   // full or unwritable: Mesa would die of SIGBUS on its mapped index
    disable();
    return;
  }
  use_dir(settings.driver_dir());
}

MesaShaderCacheState mesa_shader_cache_state() {
  MesaShaderCacheState s;
  std::optional<bool> disabled = as_boolean(env(kDisable));
  if (!disabled) disabled = as_boolean(env("MESA_GLSL_CACHE_DISABLE"));
  if (disabled.value_or(false)) {
    s.enabled = false;
    return s;
  }
  namespace fs = std::filesystem;
  if (auto dir = env(kDir); dir && !dir->empty())
    s.dir = *dir;
  else if (auto glsl = env("MESA_GLSL_CACHE_DIR"); glsl && !glsl->empty())
    s.dir = *glsl;
  else if (auto xdg = env("XDG_CACHE_HOME"); xdg && !xdg->empty())
    s.dir = (fs::path(*xdg) / "mesa_shader_cache").string();
  else if (auto home = env("HOME"); home && !home->empty())
    s.dir = (fs::path(*home) / ".cache" / "mesa_shader_cache").string();
  else
    s.enabled = false;
  return s;
}

}  // namespace shaderbed
