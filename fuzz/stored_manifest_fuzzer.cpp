// libFuzzer target: the stored-images manifest reader (run/StoredManifest.h
// parse_stored_manifest), which `run --against DIR` and `run --save-images DIR` apply to
// DIR/manifest.json, a file a user may have edited. It must refuse with an error, never
// throw or crash; no entry it accepts may leave the folder; and what it accepts survives
// the round trip: write -> read -> write is exact.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "FuzzSupport.h"
#include "run/StoredManifest.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderbed;
  auto manifest = parse_stored_manifest(fuzz::as_text(data, size), "manifest.json");
  if (!manifest) {
    (void)manifest.error().to_string();
    return 0;
  }
  for (const auto& [id, image] : manifest->images) {
    const std::filesystem::path file(image.file);
    bool leaves = file.is_absolute() || file.empty();
    for (const auto& part : file) leaves = leaves || part == "..";
    if (leaves) {
      std::fprintf(stderr, "entry '%s' names '%s', outside the folder\n", id.c_str(), image.file.c_str());
      std::abort();
    }
  }
  const std::string written = stored_manifest_text(*manifest);
  auto again = parse_stored_manifest(written, "written.json");
  if (!again) {
    std::fprintf(stderr, "the reader refused what the writer wrote: %s\n", again.error().to_string().c_str());
    std::abort();
  }
  if (stored_manifest_text(*again) != written) {
    std::fprintf(stderr, "write -> read -> write changed the text\n");
    std::abort();
  }
  return 0;
}
