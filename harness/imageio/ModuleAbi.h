#pragma once
// The C interface between shaderbed and its OpenImageIO module (module/OiioModule.cpp).
// C types only, so the module and the binary share no C++ ABI beyond this table; bump the
// symbol's version when a function changes.
#include <cstddef>

// The largest image a read decodes, checked on the file's header before any pixel is
// decoded or memory is taken for it: a small PNG can declare 30000 x 30000. Each side,
// and the bytes the image takes as float values, at least 4 a texel (the RGBA a texture
// becomes): 4096 x 4096 RGBA (a read holds two or three copies of that at once).
constexpr int kMaxImageSide = 16384;
constexpr size_t kMaxImageFloatBytes = size_t(256) << 20;

extern "C" {

struct ShaderbedImageIo {
  // 0 on success; else the message in error[error_size].
  // v3: the image encoded in memory in the format `name`'s extension picks; *bytes is
  // malloc'd *size bytes, freed with free_bytes.
  int (*encode)(const char* name, int width, int height, int channels, int is_float, const void* pixels,
                unsigned char** bytes, size_t* size, char* error, size_t error_size);
  void (*free_bytes)(unsigned char* bytes);
  // On success *pixels is malloc'd width * height * channels floats, freed with free_pixels.
  int (*read)(const char* path, int* width, int* height, int* channels, float** pixels, char* error,
              size_t error_size);
  void (*free_pixels)(float* pixels);
  // v2: one mip level of the file's first subimage, as read does; *levels is how many
  // the file has, *is_8bit whether it stores 8-bit unsigned values (value / 255 exactly).
  int (*read_level)(const char* path, int level, int* width, int* height, int* channels, int* levels, int* is_8bit,
                    float** pixels, char* error, size_t error_size);
};

// The module's one exported symbol.
const ShaderbedImageIo* shaderbed_image_io_v3();
}
