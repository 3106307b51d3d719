#include "prt/ShTransferRun.h"

#include <chrono>

#include <tbb/task_arena.h>

#include "sh/Basis.h"
#include "sh/Sampling.h"
#include "sh/TransferCache.h"

namespace shaderbed {

std::expected<ShTransferRun, std::string> run_sh_transfer(const sh::TransferScene& scene, const sh::TransferOptions& options,
                                                          bool no_cache, const std::string& cache_root,
                                                          const sh::TransferProgress& progress) {
  ShTransferRun run;
  run.threads = unsigned(tbb::this_task_arena::max_concurrency());   // what sh::compute_transfer runs on
  const auto t0 = std::chrono::steady_clock::now();
  if (no_cache || cache_root.empty()) {
    run.cache = no_cache ? "off (--no-cache)" : "off (no cache folder: set --cache-dir or $SHADERBED_CACHE_DIR)";
    auto computed = sh::compute_transfer(scene, options, progress);
    if (!computed) return std::unexpected(computed.error());
    run.transfer = std::move(*computed);
    run.reason = no_cache ? "--no-cache" : "no cache folder";
  } else {
    run.cache = "on";
    auto cached = sh::cached_transfer_report(scene, options, std::filesystem::path(cache_root) / "sh", progress);
    if (!cached) return std::unexpected(cached.error());
    run.transfer = std::move(cached->transfer);
    run.from_cache = !cached->computed;
    run.file = cached->file;
    run.reason = cached->reason;
    run.write_error = cached->write_error;
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return run;
}

size_t sh_transfer_rays(const sh::TransferScene& scene, const sh::TransferOptions& options) {
  if (options.kind == sh::TransferKind::unshadowed) return 0;
  std::vector<glm::dvec3> directions;
  for (const sh::Sample& s : sh::jittered_samples(options.grid, options.seed))
    directions.push_back(sh::from_sh_frame(s.direction / glm::length(s.direction)));
  size_t above = 0;
  for (const sh::TransferMesh& mesh : scene.meshes())
    for (const glm::dvec3& normal : mesh.normals)
      for (const glm::dvec3& d : directions) above += glm::dot(normal, d) > 0.0 ? 1 : 0;
  return above * size_t(1 + (options.kind == sh::TransferKind::interreflected ? options.bounces : 0));
}

}  // namespace shaderbed
