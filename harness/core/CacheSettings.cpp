#include "core/CacheSettings.h"

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <optional>

namespace shaderbed {
namespace {

std::optional<std::string> env(const char* name) {
  const char* v = std::getenv(name);
  if (v == nullptr || *v == '\0') return std::nullopt;
  return std::string(v);
}

std::mutex settings_mutex;
std::optional<CacheSettings> settings;  // guarded by settings_mutex

std::string under(const std::string& root, const char* leaf) {
  return root.empty() ? std::string() : (std::filesystem::path(root) / leaf).string();
}

}  // namespace

std::string CacheSettings::driver_dir() const { return under(root, "mesa"); }
std::string CacheSettings::compile_dir() const { return under(root, "compile"); }

CacheSettings cache_settings_from_environment() {
  namespace fs = std::filesystem;
  CacheSettings s;
  if (auto dir = env("SHADERBED_CACHE_DIR"))
    s.root = *dir;
  else if (auto xdg = env("XDG_CACHE_HOME"))
    s.root = (fs::path(*xdg) / "shaderbed").string();
  else if (auto home = env("HOME"))
    s.root = (fs::path(*home) / ".cache" / "shaderbed").string();
  // Mesa resolves a relative MESA_SHADER_CACHE_DIR against its own working directory at
  // driver load; an absolute root means the same folder whatever changes directory later.
  if (!s.root.empty()) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(s.root, ec);
    if (!ec) s.root = absolute.lexically_normal().string();
  }
  return s;
}

CacheSettings cache_settings() {
  const std::lock_guard lock(settings_mutex);
  if (!settings) settings = cache_settings_from_environment();
  return *settings;
}

void set_cache_settings(CacheSettings s) {
  if (!s.root.empty()) {
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(s.root, ec);
    if (!ec) s.root = absolute.lexically_normal().string();
  }
  const std::lock_guard lock(settings_mutex);
  settings = std::move(s);
}

}  // namespace shaderbed
