#include "run/TextureFiles.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>

#include "backends/TextureShape.h"
#include "core/BoundedFile.h"
#include "imageio/ImageIoModule.h"

namespace shaderbed {
namespace fs = std::filesystem;
namespace {

// No texture file is this large; the decoded size is bounded by the header (ModuleAbi.h).
constexpr size_t kMaxTextureFileBytes = size_t(1) << 30;

Error at_binding(const TextureBinding& b, const std::string& case_path, std::string message) {
  return Error{.message = std::move(message), .file = case_path, .line = b.line, .column = b.column, .stage = ErrorStage::texture};
}

// A file's name as the case wrote it would be nicer, but the absolute path is what
// was tried; keep it short by showing it relative to the case's shader root.
std::string shown(const std::string& file, const std::string& case_path) {
  const fs::path root = fs::path(case_path).parent_path().parent_path();
  const fs::path relative = fs::path(file).lexically_relative(root);
  return relative.empty() || relative.string().starts_with("..") ? file : relative.string();
}

// Interleaved values of `channels` per texel -> RGBA.
std::vector<float> to_rgba(const ImagePixels& image) {
  const size_t texels = size_t(image.width) * image.height;
  std::vector<float> rgba(texels * 4);
  for (size_t i = 0; i < texels; ++i) {
    const float* in = &image.values[i * size_t(image.channels)];
    float* out = &rgba[i * 4];
    switch (image.channels) {
      case 1: out[0] = out[1] = out[2] = in[0]; out[3] = 1; break;
      case 2: out[0] = out[1] = out[2] = in[0]; out[3] = in[1]; break;
      case 3: out[0] = in[0]; out[1] = in[1]; out[2] = in[2]; out[3] = 1; break;
      default: out[0] = in[0]; out[1] = in[1]; out[2] = in[2]; out[3] = in[3]; break;
    }
  }
  return rgba;
}

// The next level by a 2x2 box filter (odd extents clamp the second texel), averaged in
// linear light: sRGB texels are decoded first and the result encoded again, 8-bit
// results are rounded to the nearest stored value.
std::vector<float> half_level(const std::vector<float>& level, uint32_t w, uint32_t h, uint32_t layers,
                              TexelFormat format) {
  const uint32_t hw = std::max(1u, w / 2), hh = std::max(1u, h / 2);
  const bool srgb = format == TexelFormat::rgba8_srgb;
  const bool eight_bit = srgb || format == TexelFormat::rgba8_unorm;
  std::vector<float> out(size_t(hw) * hh * 4 * layers);
  for (uint32_t layer = 0; layer < layers; ++layer)
    for (uint32_t y = 0; y < hh; ++y)
      for (uint32_t x = 0; x < hw; ++x)
        for (uint32_t c = 0; c < 4; ++c) {
          double sum = 0;
          for (uint32_t dy = 0; dy < 2; ++dy)
            for (uint32_t dx = 0; dx < 2; ++dx) {
              const uint32_t sx = std::min(2 * x + dx, w - 1), sy = std::min(2 * y + dy, h - 1);
              const double v = level[((size_t(layer) * h + sy) * w + sx) * 4 + c];
              sum += srgb && c < 3 ? srgb_to_linear(v) : v;
            }
          double v = sum / 4;
          if (srgb && c < 3) v = linear_to_srgb(v);
          if (eight_bit) v = std::round(v * 255) / 255;
          out[((size_t(layer) * hh + y) * hw + x) * 4 + c] = float(v);
        }
  return out;
}

struct Face {
  int width = 0, height = 0;
  bool eight_bit = false;
  std::vector<std::vector<float>> levels;   // RGBA
};

Result<Face> read_face(const std::string& name, const TextureBinding& b, const std::string& file,
                       const std::string& case_path) {
  if (!fs::exists(file))
    return std::unexpected(at_binding(b, case_path, "texture '" + name + "': no image file '" + shown(file, case_path) +
                                                        "' (paths are relative to the case's shader root)"));
  // A FIFO would block OpenImageIO's open and /dev/zero feed it forever: only a regular
  // file of a size an image can have reaches it (its header then bounds the decode).
  if (auto ok = check_bounded_file(file, "the image file", ErrorStage::texture, kMaxTextureFileBytes); !ok)
    return std::unexpected(at_binding(b, case_path, "texture '" + name + "': cannot read '" + shown(file, case_path) +
                                                        "': " + ok.error().message));
  const bool file_levels = b.mipmaps == MipSource::file;
  auto read = read_image_levels(file, file_levels);
  if (!read)
    return std::unexpected(at_binding(b, case_path, "texture '" + name + "': cannot read '" + shown(file, case_path) +
                                                        "': " + read.error().message));
  if (file_levels && read->levels.size() < 2)
    return std::unexpected(at_binding(b, case_path, "texture '" + name + "': '" + shown(file, case_path) +
                                                        "' has no mip levels of its own (mipmaps = \"file\"); "
                                                        "mipmaps = true generates them"));
  Face face{.width = read->levels[0].width, .height = read->levels[0].height, .eight_bit = read->eight_bit};
  if (face.width <= 0 || face.height <= 0 || read->levels[0].channels <= 0)
    return std::unexpected(at_binding(b, case_path, "texture '" + name + "': '" + shown(file, case_path) +
                                                        "' has no pixels"));
  for (const ImagePixels& level : read->levels) face.levels.push_back(to_rgba(level));
  return face;
}

Result<Texture> load(const std::string& name, const TextureBinding& b, const std::string& case_path) {
  if (b.files.empty())
    return std::unexpected(at_binding(b, case_path, "texture '" + name + "' names no file (file = \"...\")"));
  std::vector<Face> faces;
  for (const std::string& file : b.files) {
    auto face = read_face(name, b, file, case_path);
    if (!face) return std::unexpected(face.error());
    if (!faces.empty() && (face->width != faces[0].width || face->height != faces[0].height ||
                           face->eight_bit != faces[0].eight_bit || face->levels.size() != faces[0].levels.size()))
      return std::unexpected(at_binding(b, case_path, "texture '" + name + "': cube face '" + shown(file, case_path) +
                                                          "' differs from '" + shown(b.files[0], case_path) +
                                                          "' in size, bit depth or mip levels"));
    faces.push_back(std::move(*face));
  }
  const bool srgb = b.settings.srgb.value_or(false);
  Texture t{.name = name, .dimensions = 2, .width = uint32_t(faces[0].width), .height = uint32_t(faces[0].height)};
  t.cube = faces.size() == 6;
  if (t.cube && t.width != t.height)
    return std::unexpected(at_binding(b, case_path, "texture '" + name + "': cube faces must be square, not " +
                                                        extent_text(t)));
  t.format = faces[0].eight_bit ? (srgb ? TexelFormat::rgba8_srgb : TexelFormat::rgba8_unorm) : TexelFormat::rgba32_float;
  const size_t levels = faces[0].levels.size();
  for (size_t level = 0; level < levels; ++level) {
    std::vector<float> values;
    for (const Face& f : faces) values.insert(values.end(), f.levels[level].begin(), f.levels[level].end());
    // No float sRGB format exists: decode here what the sampler would have decoded.
    if (srgb && t.format == TexelFormat::rgba32_float)
      for (size_t i = 0; i < values.size(); ++i)
        if (i % 4 != 3) values[i] = float(srgb_to_linear(values[i]));
    if (level == 0) t.texels = std::move(values);
    else t.mip_levels.push_back(std::move(values));
  }
  if (b.mipmaps == MipSource::generate) {
    uint32_t w = t.width, h = t.height;
    const std::vector<float>* previous = &t.texels;
    while (w > 1 || h > 1) {
      t.mip_levels.push_back(half_level(*previous, w, h, t.cube ? 6 : 1, t.format));
      previous = &t.mip_levels.back();
      w = std::max(1u, w / 2);
      h = std::max(1u, h / 2);
    }
  }
  return t;
}

}  // namespace

Result<Texture> read_texture_file(const std::string& name, const TextureBinding& binding, const std::string& case_path) {
  return load(name, binding, case_path);
}

double srgb_to_linear(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }
double linear_to_srgb(double v) { return v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1 / 2.4) - 0.055; }

Result<std::shared_ptr<const Texture>> load_texture_file(const std::string& name, const TextureBinding& binding,
                                                         const std::string& case_path) {
  // Keyed by everything that shapes the texels; cases and cells share what they load.
  std::string key = name + '\n' + std::to_string(int(binding.mipmaps.value_or(MipSource::none))) + '\n' +
                    std::to_string(binding.settings.srgb.value_or(false));
  for (const std::string& f : binding.files) {
    std::error_code ec;
    const auto stamp = fs::last_write_time(f, ec);
    key += '\n' + f + '@' + (ec ? std::string("?") : std::to_string(stamp.time_since_epoch().count()));
  }
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const Texture>> loaded;
  {
    const std::lock_guard lock(mutex);
    if (auto it = loaded.find(key); it != loaded.end()) return it->second;
  }
  auto texture = load(name, binding, case_path);
  if (!texture) return std::unexpected(texture.error());
  auto shared = std::make_shared<const Texture>(std::move(*texture));
  const std::lock_guard lock(mutex);
  return loaded.emplace(key, shared).first->second;
}

}  // namespace shaderbed
