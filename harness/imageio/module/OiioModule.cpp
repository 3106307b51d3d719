// The OpenImageIO side of image I/O, built as a module that shaderbed dlopens on the first
// image read or write (ImageIoModule.h says why).
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "imageio/ModuleAbi.h"

namespace {

int failed(const std::string& message, char* error, size_t error_size) {
  if (error_size > 0) {
    std::strncpy(error, message.c_str(), error_size - 1);
    error[error_size - 1] = '\0';
  }
  return 1;
}

// Alpha as the file stores it: OpenImageIO would premultiply it into RGB on reading (and
// divide it out on writing), but shaders keep masks, roughness or heights in alpha and
// must see the file's own values, as a GPU's texture upload gives them.
OIIO::ImageSpec unassociated_alpha() {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  return config;
}

// The header's extents against kMaxImageSide and kMaxImageFloatBytes; "" within them.
std::string over_budget(const OIIO::ImageSpec& spec) {
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1)
    return "declares an image of " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + "x" +
           std::to_string(spec.depth) + " with " + std::to_string(spec.nchannels) + " channels";
  const std::string extent = std::to_string(spec.width) + "x" + std::to_string(spec.height);
  if (spec.width > kMaxImageSide || spec.height > kMaxImageSide)
    return "declares " + extent + " pixels, over the " + std::to_string(kMaxImageSide) + " a side an image may have";
  const size_t bytes = size_t(spec.width) * size_t(spec.height) * size_t(std::max(spec.nchannels, 4)) * sizeof(float);
  if (bytes > kMaxImageFloatBytes)
    return "declares " + extent + " pixels with " + std::to_string(spec.nchannels) + " channels, " +
           std::to_string(bytes >> 20) + " MiB as float, over the " + std::to_string(kMaxImageFloatBytes >> 20) +
           " MiB an image may take";
  return "";
}

// Encoded in memory, for shaderbed to write with checked writes: OpenImageIO's own file
// writers report success when the disk fills (a 0-byte PNG or a short EXR).
int encode(const char* name, int width, int height, int channels, int is_float, const void* pixels,
           unsigned char** bytes, size_t* size, char* error, size_t error_size) {
  OIIO::ImageSpec spec(width, height, channels, is_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  auto out = OIIO::ImageOutput::create(name);
  if (!out) return failed("no image writer: " + OIIO::geterror(), error, error_size);
  if (!out->supports("ioproxy")) return failed(std::string(out->format_name()) + " cannot be encoded in memory", error, error_size);
  OIIO::Filesystem::IOVecOutput memory;
  if (!out->set_ioproxy(&memory) || !out->open(name, spec) || !out->write_image(spec.format, pixels) || !out->close())
    return failed(out->geterror(), error, error_size);
  const std::vector<unsigned char>& encoded = memory.buffer();
  *bytes = static_cast<unsigned char*>(std::malloc(std::max<size_t>(encoded.size(), 1)));
  if (!*bytes) return failed("out of memory", error, error_size);
  std::memcpy(*bytes, encoded.data(), encoded.size());
  *size = encoded.size();
  return 0;
}

void free_bytes(unsigned char* bytes) { std::free(bytes); }

int read(const char* path, int* width, int* height, int* channels, float** pixels, char* error, size_t error_size) {
  const OIIO::ImageSpec config = unassociated_alpha();
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) return failed(OIIO::geterror(), error, error_size);
  const OIIO::ImageSpec& spec = in->spec();
  if (const std::string over = over_budget(spec); !over.empty()) return failed(over, error, error_size);
  const size_t count = size_t(spec.width) * spec.height * spec.nchannels;
  auto* data = static_cast<float*>(std::malloc(count * sizeof(float)));
  if (!data) return failed("out of memory", error, error_size);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, data)) {
    std::free(data);
    return failed(in->geterror(), error, error_size);
  }
  *width = spec.width;
  *height = spec.height;
  *channels = spec.nchannels;
  *pixels = data;
  return 0;
}

int read_level(const char* path, int level, int* width, int* height, int* channels, int* levels, int* is_8bit,
               float** pixels, char* error, size_t error_size) {
  const OIIO::ImageSpec config = unassociated_alpha();
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) return failed(OIIO::geterror(), error, error_size);
  int count = 1;
  while (in->seek_subimage(0, count)) ++count;
  if (level < 0 || level >= count)
    return failed("has no mip level " + std::to_string(level) + " (it has " + std::to_string(count) + ")", error,
                  error_size);
  if (!in->seek_subimage(0, level)) return failed(in->geterror(), error, error_size);
  const OIIO::ImageSpec& spec = in->spec();
  if (const std::string over = over_budget(spec); !over.empty()) return failed(over, error, error_size);
  const size_t values = size_t(spec.width) * spec.height * spec.nchannels;
  auto* data = static_cast<float*>(std::malloc(values * sizeof(float)));
  if (!data) return failed("out of memory", error, error_size);
  if (!in->read_image(0, level, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, data)) {
    std::free(data);
    return failed(in->geterror(), error, error_size);
  }
  *width = spec.width;
  *height = spec.height;
  *channels = spec.nchannels;
  *levels = count;
  *is_8bit = spec.format == OIIO::TypeDesc::UINT8;
  *pixels = data;
  return 0;
}

void free_pixels(float* pixels) { std::free(pixels); }

const ShaderbedImageIo kTable{encode, free_bytes, read, free_pixels, read_level};

}  // namespace

extern "C" __attribute__((visibility("default"))) const ShaderbedImageIo* shaderbed_image_io_v3() { return &kTable; }
