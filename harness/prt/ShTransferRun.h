#pragma once
// A shape's per-vertex transfer for `shaderbed sh`: read from the cache the run engine uses
// (<cache root>/sh) or computed, timed, with why it was computed.
#include <expected>
#include <filesystem>
#include <string>
#include <vector>

#include "sh/Transfer.h"
#include "sh/TransferScene.h"

namespace shaderbed {

struct ShTransferRun {
  std::vector<sh::VertexTransfer> transfer;   // per mesh: the shape, then the ground
  bool from_cache = false;
  std::string cache;          // "on", or why it is off
  std::filesystem::path file; // the cache file ("" without a cache)
  std::string reason;         // why it was computed
  std::string write_error;    // the computed transfer could not be stored (not a failure)
  double seconds = 0;
  unsigned threads = 1;       // the cores it was (or would be) spread over
};

// `cache_root` "" = no cache folder; `no_cache` computes and stores nothing either way.
std::expected<ShTransferRun, std::string> run_sh_transfer(const sh::TransferScene& scene, const sh::TransferOptions& options,
                                                          bool no_cache, const std::string& cache_root,
                                                          const sh::TransferProgress& progress);

// The rays the transfer casts: one per sample above each vertex's horizon, in the direct
// pass (shadowed) and in each bounce (closest hits); none unshadowed.
size_t sh_transfer_rays(const sh::TransferScene& scene, const sh::TransferOptions& options);

}  // namespace shaderbed
