#pragma once
// Per-vertex transfer cached on disk: the precomputation is minutes of ray casting for a
// dense mesh, and its result depends only on the key below. The book's D3DX sample
// validates a cached buffer against the mesh by order and vertex count alone (digest
// §3.3); here the key is everything the result depends on, so a stale file is never
// served:
//   - every mesh's positions, normals (as the scene normalised them), indices and albedo,
//   - the sample directions and weights themselves (not only grid and seed: a change in
//     the sampler invalidates too), the seed and grid,
//   - bands, kind, bounces (counted for the inter-reflected kind only, where they matter),
//   - transfer_cache_version.
// A file is used only if its header holds exactly this key and the payload's size and
// checksum match; anything else (missing, truncated, corrupt, another key hashed to the
// same name) is recomputed and rewritten atomically (a temporary file renamed over it).
#include <cstdint>
#include <expected>
#include <filesystem>
#include <string>
#include <vector>

#include "sh/Transfer.h"

namespace sh {

// Bump when the file format or anything in the transfer computation changes its numbers.
inline constexpr uint32_t transfer_cache_version = 1;

struct CachedTransfer {
  std::vector<VertexTransfer> transfer;
  bool computed = false;        // false: read from `file`
  std::filesystem::path file;   // the cache file for this key
  std::string reason;           // why it was computed ("no cache file", "checksum mismatch", ...)
  std::string write_error;      // set if the result could not be stored (the result is still valid)
};

// The transfer for this scene and options, from cache_dir if a valid file is there, else
// computed (progress as compute_transfer) and stored. cache_dir is created if missing.
std::expected<CachedTransfer, std::string> cached_transfer_report(const TransferScene& scene, const TransferOptions& options,
                                                                  const std::filesystem::path& cache_dir,
                                                                  const TransferProgress& progress = {});

// The same, the transfer alone; a failure to write the cache is not an error (the
// computed transfer is returned either way).
std::expected<std::vector<VertexTransfer>, std::string> cached_transfer(const TransferScene& scene, const TransferOptions& options,
                                                                        const std::filesystem::path& cache_dir,
                                                                        const TransferProgress& progress = {});

}  // namespace sh
