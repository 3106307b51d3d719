#pragma once
// A case's image files as textures (`[textures] NAME = { file = "...", ... }`), read
// through OpenImageIO (imageio/ImageIoModule.h): any format it reads (PNG, EXR, HDR,
// TGA, DDS, ...), expanded to RGBA (grey g -> (g, g, g, 1), RGB -> (r, g, b, 1)).
// 8-bit files stay 8-bit on the device (RGBA8, or sRGB8_A8 with color = "srgb", which
// the sampler decodes); anything else is RGBA32F, decoded to linear on the CPU when the
// case says sRGB. Mip levels are the file's own (mipmaps = "file") or generated here by
// a 2x2 box filter in linear light (mipmaps = true), so every backend samples the same
// texels. Six files make a cube map. Loaded textures are kept for the process.
#include <memory>
#include <string>

#include "backends/Backend.h"
#include "core/Error.h"
#include "scene/CaseFile.h"

namespace shaderbed {

// Errors (a missing file, an unreadable image, faces that disagree) point at the case
// file's line that binds the texture and name the texture and the image file. Only a
// regular file is opened (a FIFO or /dev/zero is refused), and its header must declare an
// image within kMaxImageSide and kMaxImageFloatBytes (imageio/ModuleAbi.h) before any
// pixel is decoded: a decompression bomb is an error of stage "texture", not a crash.
Result<std::shared_ptr<const Texture>> load_texture_file(const std::string& name, const TextureBinding& binding,
                                                         const std::string& case_path);
// The same, read again every time and kept nowhere (load_texture_file keeps what it loads
// for the process): for the texture loader's fuzz target.
Result<Texture> read_texture_file(const std::string& name, const TextureBinding& binding, const std::string& case_path);

// sRGB transfer functions (IEC 61966-2-1), as the samplers' sRGB decode applies them.
double srgb_to_linear(double encoded);
double linear_to_srgb(double linear);

}  // namespace shaderbed
