#include "pipeline/Texture.h"

namespace shaderbed {

const char* to_string(TexelFormat f) {
  switch (f) {
    case TexelFormat::r32_float: return "R32F";
    case TexelFormat::rgba32_float: return "RGBA32F";
    case TexelFormat::rgba8_unorm: return "RGBA8";
    case TexelFormat::rgba8_srgb: return "sRGB8_A8";
  }
  return "?";
}

}  // namespace shaderbed
