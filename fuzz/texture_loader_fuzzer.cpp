// libFuzzer target: the texture loader (run/TextureFiles.h read_texture_file), the bounded
// path every case texture takes: a regular file of bounded size, OpenImageIO's header, the
// image's extents against the budget (imageio/ModuleAbi.h), then decode, RGBA and mip
// levels. The first byte picks the file's extension (which format OpenImageIO tries
// first) and whether mip levels are the file's own or generated; the rest is the file.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "FuzzSupport.h"
#include "run/TextureFiles.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderbed;
  if (size == 0) return 0;
  static const char* const kExtensions[] = {".png", ".exr", ".tga", ".hdr", ".dds", ".jpg", ".bmp", ".tif"};
  const uint8_t choice = data[0];
  const std::string file = fuzz::write_scratch(fuzz::as_text(data + 1, size - 1), "textures",
                                               std::string("texture") + kExtensions[choice % 8]);
  TextureBinding binding;
  binding.files = {file};
  binding.mipmaps = (choice & 8) ? MipSource::file : (choice & 16) ? MipSource::generate : MipSource::none;
  auto texture = read_texture_file("fuzzed", binding, fuzz::write_scratch("", "cases", "fuzz.toml"));
  if (!texture) {
    (void)texture.error().to_string();
    return 0;
  }
  // What it accepted is whole: level 0's RGBA texels for its extent.
  if (texture->width == 0 || texture->height == 0 ||
      texture->texels.size() != size_t(texture->width) * texture->height * 4) {
    std::fprintf(stderr, "a loaded texture's texels do not fill its %ux%u extent\n", texture->width, texture->height);
    std::abort();
  }
  return 0;
}
