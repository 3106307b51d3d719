#pragma once
// A run's renders kept so later runs can be judged against them: `run --save-images DIR`
// writes every drawn cell's image (EXR: R, G, B, A exactly as drawn, and a fifth channel
// holding coverage) and DIR/manifest.json; `run --against DIR` or a case's
// `reference = { images = "DIR" }` compares each cell with its own stored image. This is
// how today's port is checked against yesterday's known-good run, or lavapipe against
// images drawn on real hardware.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "compare/ImageComparison.h"
#include "core/Error.h"
#include "core/Image.h"
#include "report/Results.h"
#include "run/StoredManifest.h"
#include "scene/CaseFile.h"

namespace shaderbed {

struct StoredRun {
  std::string dir;
  int size = 0;                                // width = height of every image
  ToolVersions tools;                          // the toolchain that drew them
  std::map<std::string, StoredImage> images;   // by cell id (CellResult::id)
};

// Where a cell's image goes under `dir`: <case>/<variant>/<shape>/<language>-<backend>-<path>.exr.
std::string stored_image_file(const CellResult& r);

// Writes one cell's render under `dir` (whole or not at all: a temporary file renamed).
// A run writes into its staging folder (run/StagedStoredImages.h), never into the set.
Result<void> save_stored_image(const std::string& dir, const CellResult& r, const Image& image);

// Reads DIR/manifest.json (run/StoredManifest.h); `size` must match the run's (a clear
// error otherwise).
Result<StoredRun> load_stored_run(const std::string& dir, int size);

// The stored image of cell `id` as a reference (coverage from its fifth channel); a file
// that is not a regular one of a plausible size is refused before it is decoded.
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

// The folders of stored images the run is judged against: `against_dir` (--against), or
// else each case's `reference = { images = ... }`, with who names it ("--against", "case 'x'").
std::vector<std::pair<std::string, std::string>> stored_reference_dirs(const std::string& against_dir,
                                                                       const std::vector<Case>& cases);

// Refuses, before anything is drawn, folders that would overwrite stored images: --out or
// --save-images that is (or is inside, or holds) a folder the run is judged against, and
// --out that is (or is inside, or holds) --save-images. Compared as canonical paths, so a
// symlink or `a/../a` is the same folder.
Result<void> check_stored_folders(const std::string& out_dir, const std::string& save_images_dir,
                                  const std::vector<std::pair<std::string, std::string>>& judged_by);

// "" when the toolchains drew alike, else what differs ("Mesa 23.1 (stored) vs 22.3.6").
std::string toolchain_difference(const ToolVersions& stored, const ToolVersions& now);

}  // namespace shaderbed
