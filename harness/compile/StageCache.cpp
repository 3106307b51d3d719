#include "compile/StageCache.h"

#include <map>
#include <mutex>
#include <optional>
#include <string>

#include "compile/CompileCache.h"
#include "compile/CrossGlsl.h"
#include "compile/IsolatedCompile.h"
#include "core/CacheSettings.h"

namespace shaderbed {
namespace {

// The disk layer for the current settings, or nullopt when it is off.
std::optional<CompileCache> disk_cache() {
  const CacheSettings settings = cache_settings();
  if (!settings.compile_enabled()) return std::nullopt;
  return std::optional<CompileCache>(std::in_place, settings.compile_dir(), current_compile_toolchain(),
                                     cache_root_writable());
}

}  // namespace

Result<ShaderModule> compile_stage_cached(Language language, const ShaderSource& source, Target target) {
  static std::mutex mutex;
  static std::map<std::string, Result<ShaderModule>> modules;
  // The full inputs rather than a hash of them: a hit can never be a collision.
  std::string key = std::string(to_string(language)) + '|' + to_string(source.stage) + '|' +
                    std::to_string(int(target)) + '|' + source.entry_point + '|' + source.path + '|' + source.text;
  // The case's defines and include folders change what the same text compiles to.
  for (const auto& [name, value] : source.defines) key += "|D" + name + '=' + value;
  for (const std::string& dir : source.include_dirs) key += "|I" + dir;
  {
    const std::lock_guard lock(mutex);
    if (auto it = modules.find(key); it != modules.end()) {
      count_compile_memory_hit();
      return it->second;
    }
  }
  // Compiled outside the lock so workers compile different stages at the same time; two
  // workers racing on one stage both compile it, and the results are identical.
  Result<ShaderModule> module = [&]() -> Result<ShaderModule> {
    std::optional<CompileCache> disk = disk_cache();
    // Isolated (IsolatedCompile.h): a disk hit starts no child; a miss is compiled there,
    // and the child stores it on disk.
    if (compiles_isolated()) {
      if (disk)
        if (std::optional<ShaderModule> hit = disk->find_stage(language, source, target)) return std::move(*hit);
      count_compile_run();
      return compile_stage_isolated(language, source, target);
    }
    if (disk) return disk->stage(language, source, target);
    count_compile_run();
    return compile_stage(language, source, target);
  }();
  const std::lock_guard lock(mutex);
  return modules.emplace(std::move(key), std::move(module)).first->second;
}

Result<std::string> spirv_to_glsl_cached(const std::vector<uint32_t>& spirv, Stage stage) {
  if (std::optional<CompileCache> disk = disk_cache()) return disk->cross_glsl(spirv, stage);
  count_compile_run();
  return spirv_to_glsl(spirv, stage);
}

}  // namespace shaderbed
