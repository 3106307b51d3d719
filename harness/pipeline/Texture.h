#pragma once
// A texture of a draw, as every stage that makes one (lut/, prt/, run/TextureFiles) and
// every backend that uploads one sees it.
#include <cstdint>
#include <string>
#include <vector>

namespace shaderbed {

// How a texture's texels are stored on the device. Every format is read as float RGBA
// by the shader; the 8-bit ones are unsigned normalised, sRGB decoded to linear.
enum class TexelFormat { r32_float, rgba32_float, rgba8_unorm, rgba8_srgb };
inline uint32_t channels(TexelFormat f) { return f == TexelFormat::r32_float ? 1 : 4; }
const char* to_string(TexelFormat);

// A texture of the draw. Either a lookup texture the harness generated on the CPU (the
// role of D3DXFillTextureTX: single-channel 32-bit float, sampled as the book's LUT
// shaders assume, see SamplerSettings' defaults) or an image file a case binds
// (run/TextureFiles.h: RGBA, float or 8-bit, 2D or cube, with mip levels).
struct Texture {
  std::string name;              // what case bindings call it, e.g. "lut"
  uint32_t dimensions = 2;       // 1, 2 or 3
  uint32_t width = 1, height = 1, depth = 1;
  // Level 0: channels(format) floats per texel, x fastest, then y, then z; a cube map's
  // six faces (+X, -X, +Y, -Y, +Z, -Z) follow each other. 8-bit formats hold the stored
  // value / 255 (sRGB still encoded), so the upload is exact.
  std::vector<float> texels;
  TexelFormat format = TexelFormat::r32_float;
  bool cube = false;             // dimensions 2, depth 1, six square faces
  // Levels 1..n, each max(1, previous / 2) on every axis, laid out as level 0. Filled
  // from the file's own levels or generated on the CPU (so every backend samples the
  // same texels); empty: the texture has one level.
  std::vector<std::vector<float>> mip_levels;
};

}  // namespace shaderbed
