#pragma once
// Images on disk: EXR keeps the exact float values (NaN included), PNG is for looking.
#include <string>
#include <vector>

#include "core/Error.h"
#include "core/Image.h"

namespace shaderbed {

// RGBA float EXR of the pixels as they are.
Result<void> write_exr(const std::string& path, int width, int height, const std::vector<float>& rgba);

// 8-bit RGB PNG: colour multiplied by `scale`, clamped to [0, 1]; NaN/Inf shown magenta
// so they cannot pass for black; uncovered pixels in a dark background colour.
Result<void> write_png(const std::string& path, const Image& image, float scale = 1.0f);

// The 8-bit RGB pixels write_png writes (rows top to bottom), for showing an image on
// screen exactly as its PNG looks.
std::vector<uint8_t> png_pixels(const Image& image, float scale = 1.0f);

}  // namespace shaderbed
