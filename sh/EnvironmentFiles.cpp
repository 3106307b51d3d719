// Environment map files through OpenImageIO (EnvironmentMap.h's read, write_environment,
// write_sky_latlong). Its own target, shaderbed_sh_files: OpenImageIO links ~250 shared
// libraries, and the CLI, which reads probes through its lazily loaded image module
// (harness/prt/ProbeFile.h), must not load them at every start.
#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <string>
#include <vector>

#include "sh/EnvironmentMap.h"

namespace sh {
namespace {

std::string named(const std::filesystem::path& path, const std::string& what) { return path.string() + ": " + what; }

}  // namespace

std::expected<EnvironmentMap, std::string> EnvironmentMap::read(const std::filesystem::path& path, MapLayout layout) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return std::unexpected(named(path, "no such file"));
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return std::unexpected(named(path, "unreadable image: " + OIIO::geterror()));
  const OIIO::ImageSpec spec = in->spec();
  if (auto ok = check_image_shape(path, {spec.width, spec.height, spec.depth, spec.nchannels, spec.deep}, layout); !ok)
    return std::unexpected(ok.error());
  const int channels = spec.nchannels;
  std::vector<float> data(std::size_t(spec.width) * spec.height * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data()))
    return std::unexpected(named(path, "unreadable pixels: " + in->geterror()));

  std::vector<glm::vec3> pixels(std::size_t(spec.width) * spec.height);
  for (std::size_t p = 0; p < pixels.size(); ++p) {
    const float* v = &data[p * channels];
    pixels[p] = channels >= 3 ? glm::vec3(v[0], v[1], v[2]) : glm::vec3(v[0]);
  }
  return EnvironmentMap(layout, spec.width, spec.height, std::move(pixels));
}

std::expected<void, std::string> write_environment(const std::filesystem::path& path, MapLayout layout, int width,
                                                   int height, const RgbFunction& radiance) {
  if (width <= 0 || height <= 0) return std::unexpected(named(path, "empty image"));
  if (layout == MapLayout::angular && width != height)
    return std::unexpected(
        named(path, "angular map must be square, not " + std::to_string(width) + "x" + std::to_string(height)));
  std::vector<float> data(std::size_t(width) * height * 3);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const glm::dvec3 w = layout == MapLayout::latlong
                               ? latlong_direction({(x + 0.5) / width, (y + 0.5) / height})
                               : angular_direction({2.0 * (x + 0.5) / width - 1.0, 1.0 - 2.0 * (y + 0.5) / height});
      const glm::dvec3 value = radiance(w);
      float* p = &data[(std::size_t(y) * width + x) * 3];
      p[0] = float(value.r);
      p[1] = float(value.g);
      p[2] = float(value.b);
    }
  }
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) return std::unexpected(named(path, "no image writer: " + OIIO::geterror()));
  const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
  if (!out->open(path.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, data.data()) || !out->close())
    return std::unexpected(named(path, "cannot write: " + out->geterror()));
  return {};
}

std::expected<void, std::string> write_sky_latlong(const std::filesystem::path& path, int width, int height,
                                                   const SkyLight& sky) {
  return write_environment(path, MapLayout::latlong, width, height, [&sky](const glm::dvec3& w) { return sky(w); });
}

}  // namespace sh
