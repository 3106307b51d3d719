#pragma once
// A run's renders kept so later runs can be judged against them: `run --save-images DIR`
// writes every drawn cell's image (EXR: R, G, B, A exactly as drawn, and a fifth channel
// holding coverage) and DIR/manifest.json; `run --against DIR` or a case's
// `reference = { images = "DIR" }` compares each cell with its own stored image. This is
// how today's port is checked against yesterday's known-good run, or lavapipe against
// images drawn on real hardware.
#include <map>
#include <string>
#include <vector>

#include "compare/ImageComparison.h"
#include "core/Error.h"
#include "core/Image.h"
#include "report/Results.h"
#include "scene/CaseFile.h"

namespace shaderbed {

constexpr int kStoredImagesSchema = 1;

struct StoredImage {
  std::string file;        // relative to the folder
  std::string scene;       // the scene fingerprint it was drawn with (scene_fingerprint)
  std::string vertex_spirv_hash, fragment_spirv_hash;
};

struct StoredRun {
  std::string dir;
  int size = 0;                                // width = height of every image
  ToolVersions tools;                          // the toolchain that drew them
  std::map<std::string, StoredImage> images;   // by cell id (CellResult::id)
};

// Where a cell's image goes under `dir`: <case>/<variant>/<shape>/<language>-<backend>-<path>.exr.
std::string stored_image_file(const CellResult& r);

// Writes one cell's render under `dir` (whole or not at all: a temporary file renamed).
Result<void> save_stored_image(const std::string& dir, const CellResult& r, const Image& image);

// Adds the report's saved cells (those with artefacts.stored_exr) to DIR/manifest.json,
// keeping the entries of earlier runs for other cells; a folder of another image size is
// an error.
Result<void> write_stored_manifest(const std::string& dir, const RunReport& report, int size);

// Reads DIR/manifest.json; `size` must match the run's (a clear error otherwise).
Result<StoredRun> load_stored_run(const std::string& dir, int size);

// The stored image of cell `id` as a reference (coverage from its fifth channel).
Result<ReferenceImage> load_stored_image(const StoredRun& run, const std::string& id, const std::string& scene);

// The stored runs a run compares with, loaded (and checked) before anything is drawn.
struct StoredReferences {
  std::map<std::string, StoredRun> runs;                  // by folder
  std::map<std::string, std::string> toolchain_notes;     // by folder: "" when drawn alike
};

// Every stored run `against_dir` (--against) or else the cases name, checked against the
// run's image size `size`; a different toolchain is noted, not refused.
Result<StoredReferences> load_stored_references(const std::string& against_dir, int size,
                                                const std::vector<Case>& cases, const ToolVersions& tools);

// "" when the toolchains drew alike, else what differs ("Mesa 23.1 (stored) vs 22.3.6").
std::string toolchain_difference(const ToolVersions& stored, const ToolVersions& now);

}  // namespace shaderbed
