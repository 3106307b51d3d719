#pragma once
// Image files through OpenImageIO, reached through a small module that is dlopen'd on the
// first image read or write. OpenImageIO links ~250 shared libraries (OpenCV, GDAL,
// FFmpeg...); linked into the binary they cost every command ~0.2 s of start-up, although
// most runs (CI without --out, eval, merge, --help) never touch an image file.
#include <cstdint>
#include <string>
#include <vector>

#include "core/Error.h"

namespace shaderbed {

enum class PixelType { uint8, float32 };

struct ImagePixels {
  int width = 0, height = 0, channels = 0;
  std::vector<float> values;   // channels per pixel, rows top to bottom
};

// Writes interleaved pixels; the file name's extension picks the format (.exr, .png, ...).
// Creates the parent folder.
Result<void> write_image_file(const std::string& path, int width, int height, int channels, PixelType type,
                              const void* pixels);

// Reads any format OpenImageIO knows, as float.
Result<ImagePixels> read_image_file(const std::string& path);

struct ImageFileLevels {
  bool eight_bit = false;            // the file stores 8-bit unsigned values (each value is n / 255)
  std::vector<ImagePixels> levels;   // level 0, then the file's own mip levels (all_levels)
};

// The first image of a file, as float, and with all_levels its mip levels (DDS, tiled EXR).
Result<ImageFileLevels> read_image_levels(const std::string& path, bool all_levels);

}  // namespace shaderbed
