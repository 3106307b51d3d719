#include "compile/StageCache.h"

#include <map>
#include <mutex>
#include <string>

namespace shaderbed {

Result<ShaderModule> compile_stage_cached(Language language, const ShaderSource& source, Target target) {
  static std::mutex mutex;
  static std::map<std::string, Result<ShaderModule>> modules;
  // The full inputs rather than a hash of them: a hit can never be a collision.
  std::string key = std::string(to_string(language)) + '|' + to_string(source.stage) + '|' +
                    std::to_string(int(target)) + '|' + source.entry_point + '|' + source.path + '|' + source.text;
  {
    const std::lock_guard lock(mutex);
    if (auto it = modules.find(key); it != modules.end()) return it->second;
  }
  // Compiled outside the lock so workers compile different stages at the same time; two
  // workers racing on one stage both compile it, and the results are identical.
  Result<ShaderModule> module = compile_stage(language, source, target);
  const std::lock_guard lock(mutex);
  return modules.emplace(std::move(key), std::move(module)).first->second;
}

}  // namespace shaderbed
