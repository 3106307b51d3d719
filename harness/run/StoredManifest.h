#pragma once
// The manifest of a folder of stored images (DIR/manifest.json, run/StoredImages.h): its
// text read strictly (every field of the right type, every image inside the folder, the
// file a bounded regular file), and written back. A user may have edited or planted it,
// so nothing in it is trusted: a wrong field is one clear error naming the manifest and
// the entry, never an exception, and no entry may name a file outside the folder.
#include <cstddef>
#include <map>
#include <string>
#include <string_view>

#include "core/Error.h"
#include "report/Results.h"

namespace shaderbed {

constexpr int kStoredImagesSchema = 1;
// A manifest entry is ~300 bytes: 64 MiB is some 200,000 cells, more than any run draws.
constexpr size_t kMaxStoredManifestBytes = size_t(64) << 20;

struct StoredImage {
  std::string file;        // relative to the folder, never leaving it
  std::string scene;       // the scene fingerprint it was drawn with (scene_fingerprint)
  std::string vertex_spirv_hash, fragment_spirv_hash;
  bool operator==(const StoredImage&) const = default;
};

struct StoredManifest {
  int size = 0;                                // width = height of every image
  ToolVersions tools;                          // the toolchain that drew them
  std::map<std::string, StoredImage> images;   // by cell id (CellResult::id)
};

// `text` as a manifest; `path` names it in errors.
Result<StoredManifest> parse_stored_manifest(std::string_view text, const std::string& path);

// DIR/manifest.json's text, as parse_stored_manifest reads it back.
std::string stored_manifest_text(const StoredManifest& manifest);

// The manifest file at `path` (a regular file of at most kMaxStoredManifestBytes), parsed.
Result<StoredManifest> read_stored_manifest(const std::string& path);

}  // namespace shaderbed
