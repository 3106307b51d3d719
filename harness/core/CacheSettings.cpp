#include "core/CacheSettings.h"

#include <fcntl.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
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

// A child shaderbed inherits this once its parent printed the note for the same root.
constexpr const char* kNotedMarker = "SHADERBED_CACHE_FOLDER_NOTED";
constexpr size_t kProbeBytes = size_t(256) << 10;

std::string mib(uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

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

namespace shaderbed {

std::string cache_folder_problem(const std::string& dir, uint64_t min_free_bytes) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return "cannot be created (" + ec.message() + ")";
  struct statvfs vfs {};
  if (::statvfs(dir.c_str(), &vfs) != 0) return std::string("cannot be examined (") + std::strerror(errno) + ")";
  const uint64_t free_bytes = uint64_t(vfs.f_bavail) * vfs.f_frsize;
  if (free_bytes < min_free_bytes)
    return "has " + mib(free_bytes) + " free, under the " + mib(min_free_bytes) + " a cache needs";
  // Permission bits alone do not say it (root writes anywhere; read-only mounts, quotas).
  std::string probe = (fs::path(dir) / ".write-probe-XXXXXX").string();
  const int fd = ::mkstemp(probe.data());
  if (fd < 0) return std::string("is not writable (") + std::strerror(errno) + ")";
  const std::string zeros(kProbeBytes, '\0');
  int failure = 0;
  for (size_t done = 0; failure == 0 && done < zeros.size();) {
    const ssize_t n = ::write(fd, zeros.data() + done, zeros.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) failure = n < 0 ? errno : ENOSPC;
    else done += size_t(n);
  }
  if (::close(fd) != 0 && failure == 0) failure = errno;
  ::unlink(probe.c_str());
  if (failure != 0) return "cannot take a " + std::to_string(kProbeBytes >> 10) + " KiB write (" + std::strerror(failure) + ")";
  return "";
}

bool cache_root_writable() {
  const CacheSettings s = cache_settings();
  if (s.root.empty() || (!s.driver && !s.compile)) return true;   // nothing would be written
  static std::mutex mutex;
  static std::map<std::string, bool> decided;   // guarded by mutex
  const std::lock_guard lock(mutex);
  if (auto it = decided.find(s.root); it != decided.end()) return it->second;
  const std::string problem = cache_folder_problem(s.root);
  if (!problem.empty()) {
    const char* noted = std::getenv(kNotedMarker);
    if (noted == nullptr || s.root != noted) {
      std::fprintf(stderr, "shaderbed: note: the cache folder %s %s; running without Mesa's shader cache and without "
                   "compile-cache writes\n", s.root.c_str(), problem.c_str());
      ::setenv(kNotedMarker, s.root.c_str(), 1);
    }
  }
  return decided.emplace(s.root, problem.empty()).first->second;
}

}  // namespace shaderbed
