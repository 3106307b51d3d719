// CPU texture sampling with Vulkan's rules as lavapipe (llvmpipe's gallivm sampler) applies
// them, in double: texel coordinates, wrapping, sRGB decode before filtering, LOD and mip
// selection, cube face selection.
#include "twin/TextureSampling.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstddef>
#include <limits>

namespace twin {
namespace {

using Rgba = std::array<double, 4>;

// Unnormalised coordinates are clamped to this before floor() and the int64 conversion:
// beyond it the conversion would be undefined (1e30, inf), and below 2^53 floor() and
// the fraction stay exact. No texture is anywhere near this wide.
constexpr double kCoordinateLimit = 1e15;

// NaN becomes 0 (texel 0, weight 0) rather than an indeterminate index.
double finite_coordinate(double u) {
  if (std::isnan(u)) return 0;
  return std::clamp(u, -kCoordinateLimit, kCoordinateLimit);
}

uint32_t dimension_count(const TextureImage& image) {
  if (image.cube) return 2;
  return std::clamp<uint32_t>(image.dimensions, 1, 3);
}

uint32_t minified(uint32_t size, int level) {
  // A shift of 32 or more is undefined; every size is 1 by then anyway.
  const int shift = std::clamp(level, 0, 31);
  return std::max<uint32_t>(1, size >> shift);
}

// Level sizes on the three axes, with the axes the texture does not have at 1.
std::array<int64_t, 3> extent(const TextureImage& image, int level) {
  const uint32_t dims = dimension_count(image);
  return {int64_t{minified(image.width, level)}, dims >= 2 ? int64_t{minified(image.height, level)} : 1,
          dims >= 3 ? int64_t{minified(image.depth, level)} : 1};
}

double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// The texel at float offset `offset` of `data` as RGBA: missing G and B are 0, missing A
// is 1. Data shorter than the size says (a bad upload) reads as zero, never out of bounds.
Rgba read_texel(const TextureImage& image, std::span<const float> data, size_t offset, bool srgb) {
  const size_t channels = image.channels;
  if (channels == 0 || offset > data.size() || data.size() - offset < channels) return {0, 0, 0, 0};
  Rgba texel{0, 0, 0, 1};
  for (size_t c = 0; c < std::min<size_t>(channels, 4); ++c) texel[c] = data[offset + c];
  if (srgb)
    for (size_t c = 0; c < 3; ++c) texel[c] = srgb_to_linear(texel[c]);
  return texel;
}

// The border colour as a texel of this image. Like llvmpipe it replaces only the channels
// the format has (a 1-channel image's border texel is (Br, 0, 0, 1)), is clamped to [0, 1]
// for normalised formats, and is not sRGB-decoded (it is given in linear).
Rgba border_texel(const TextureImage& image, const SamplerState& sampler) {
  Rgba texel{0, 0, 0, 1};
  for (size_t c = 0; c < std::min<size_t>(image.channels, 4); ++c) texel[c] = sampler.border[c];
  if (image.unorm8)
    for (double& c : texel) c = std::clamp(c, 0.0, 1.0);
  return texel;
}

// An integer texel index after the address mode; -1 means "border texel".
int64_t address(int64_t i, int64_t size, Address mode) {
  switch (mode) {
    case Address::wrap: {
      const int64_t r = i % size;
      return r < 0 ? r + size : r;
    }
    case Address::mirror: {
      // VK spec: (size - 1) - mirror((i mod 2size) - size), which is this.
      int64_t t = i % (2 * size);
      if (t < 0) t += 2 * size;
      return t < size ? t : 2 * size - 1 - t;
    }
    case Address::clamp:
      return std::clamp<int64_t>(i, 0, size - 1);
    case Address::border:
      return i < 0 || i >= size ? -1 : i;
  }
  return std::clamp<int64_t>(i, 0, size - 1);
}

// One axis's texels and weights: one tap for nearest, two for linear.
struct AxisTaps {
  std::array<int64_t, 2> index{0, 0};
  std::array<double, 2> weight{1, 0};
  int count = 1;
};

AxisTaps axis_taps(double s, int64_t size, Filter filter, Address mode) {
  AxisTaps taps;
  const double u = finite_coordinate(s * static_cast<double>(size));
  if (filter == Filter::nearest) {
    taps.index[0] = address(static_cast<int64_t>(std::floor(u)), size, mode);
    return taps;
  }
  const double shifted = u - 0.5;
  const double i0 = std::floor(shifted);
  const double alpha = shifted - i0;
  const auto i = static_cast<int64_t>(i0);
  taps.index = {address(i, size, mode), address(i + 1, size, mode)};
  taps.weight = {1 - alpha, alpha};
  taps.count = 2;
  return taps;
}

// Filtered RGBA of one level (one face of a cube map) at normalised `st`.
Rgba filter_level(const TextureImage& image, const SamplerState& sampler, int level, int face,
                  const std::array<double, 3>& st, Filter filter, const std::array<Address, 3>& modes) {
  const std::span<const float> data = image.levels[static_cast<size_t>(level)];
  const std::array<int64_t, 3> size = extent(image, level);
  const uint32_t dims = dimension_count(image);
  std::array<AxisTaps, 3> taps;
  for (uint32_t a = 0; a < dims; ++a) taps[a] = axis_taps(st[a], size[a], filter, modes[a]);

  const size_t channels = image.channels;
  const size_t face_base = static_cast<size_t>(face) * static_cast<size_t>(size[0] * size[1]) * channels;
  const Rgba border = border_texel(image, sampler);
  Rgba result{0, 0, 0, 0};
  for (int z = 0; z < taps[2].count; ++z)
    for (int y = 0; y < taps[1].count; ++y)
      for (int x = 0; x < taps[0].count; ++x) {
        const int64_t ix = taps[0].index[x], iy = taps[1].index[y], iz = taps[2].index[z];
        const double w = taps[0].weight[x] * taps[1].weight[y] * taps[2].weight[z];
        Rgba texel;
        if (ix < 0 || iy < 0 || iz < 0) {
          texel = border;
        } else {
          const auto linear = static_cast<size_t>((iz * size[1] + iy) * size[0] + ix);
          texel = read_texel(image, data, face_base + linear * channels, sampler.srgb);
        }
        for (size_t c = 0; c < 4; ++c) result[c] += w * texel[c];
      }
  return result;
}

// Cube face selection (VK spec "Cube Map Face Selection"): the major axis is the largest
// |component|; on ties z wins over y and y over x (llvmpipe's order, from D3D10): z if
// |rz| >= |rx| and |rz| >= |ry|, else y if |ry| >= |rx|, else x. The face is negative when
// the major component's sign bit is set, as llvmpipe tests it.
struct CubeFace {
  int face = 0;        // +X, -X, +Y, -Y, +Z, -Z
  double sc = 0, tc = 0, ma = 0;
  int axis = 0;        // the major axis, 0..2
  double s_sign = 1, t_sign = 1;   // sc = s_sign * r[s_axis], tc = t_sign * r[t_axis]
  int s_axis = 0, t_axis = 0;
};

CubeFace select_face(const std::array<double, 3>& r) {
  const double ax = std::abs(r[0]), ay = std::abs(r[1]), az = std::abs(r[2]);
  CubeFace f;
  if (az >= ax && az >= ay) f.axis = 2;
  else if (ay >= ax) f.axis = 1;
  else f.axis = 0;
  const bool negative = std::signbit(r[static_cast<size_t>(f.axis)]);
  f.face = 2 * f.axis + (negative ? 1 : 0);
  // The spec's table of sc, tc per face.
  switch (f.face) {
    case 0: f.s_axis = 2, f.s_sign = -1, f.t_axis = 1, f.t_sign = -1; break;   // +X: -rz, -ry
    case 1: f.s_axis = 2, f.s_sign = +1, f.t_axis = 1, f.t_sign = -1; break;   // -X: +rz, -ry
    case 2: f.s_axis = 0, f.s_sign = +1, f.t_axis = 2, f.t_sign = +1; break;   // +Y: +rx, +rz
    case 3: f.s_axis = 0, f.s_sign = +1, f.t_axis = 2, f.t_sign = -1; break;   // -Y: +rx, -rz
    case 4: f.s_axis = 0, f.s_sign = +1, f.t_axis = 1, f.t_sign = -1; break;   // +Z: +rx, -ry
    default: f.s_axis = 0, f.s_sign = -1, f.t_axis = 1, f.t_sign = -1; break;  // -Z: -rx, -ry
  }
  f.sc = f.s_sign * r[static_cast<size_t>(f.s_axis)];
  f.tc = f.t_sign * r[static_cast<size_t>(f.t_axis)];
  f.ma = r[static_cast<size_t>(f.axis)];
  return f;
}

// Largest squared scaled derivative length -> lambda; 0 (and, as llvmpipe does for
// explicit derivatives, inf or NaN) gives -infinity, i.e. magnification.
double lambda_from_squared_rho(double rho_x2, double rho_y2) {
  const double rho2 = std::max(rho_x2, rho_y2);
  if (!(rho2 > 0) || !std::isfinite(rho2)) return -std::numeric_limits<double>::infinity();
  return 0.5 * std::log2(rho2);
}

}  // namespace

double implicit_lod(const TextureImage& image, const std::array<double, 3>& coordinate,
                    const CoordinateDerivatives& derivatives) {
  const auto& dx = derivatives.dx;
  const auto& dy = derivatives.dy;
  if (!image.cube) {
    const uint32_t dims = dimension_count(image);
    const std::array<double, 3> size{double(image.width), double(image.height), double(image.depth)};
    double rx2 = 0, ry2 = 0;
    for (uint32_t a = 0; a < dims; ++a) {
      rx2 += (dx[a] * size[a]) * (dx[a] * size[a]);
      ry2 += (dy[a] * size[a]) * (dy[a] * size[a]);
    }
    return lambda_from_squared_rho(rx2, ry2);
  }
  // Cube: s = (sc / |ma| + 1) / 2, so ds = (dsc * |ma| - sc * d|ma|) / (2 ma^2) with
  // d|ma| = sign(ma) dma. (The spec writes dma where d|ma| is meant; llvmpipe's
  // 0.5 * (dsc - sc * dma / ma) / ma is this times sign(ma), the same length.)
  const CubeFace f = select_face(coordinate);
  const double abs_ma = std::abs(f.ma);
  if (!(abs_ma > 0)) return -std::numeric_limits<double>::infinity();
  const double sign_ma = std::signbit(f.ma) ? -1.0 : 1.0;
  const double ma2 = f.ma * f.ma;
  const auto face_derivative = [&](const std::array<double, 3>& d, double& ds, double& dt) {
    const double dma_abs = sign_ma * d[static_cast<size_t>(f.axis)];
    const double dsc = f.s_sign * d[static_cast<size_t>(f.s_axis)];
    const double dtc = f.t_sign * d[static_cast<size_t>(f.t_axis)];
    ds = 0.5 * (dsc * abs_ma - f.sc * dma_abs) / ma2;
    dt = 0.5 * (dtc * abs_ma - f.tc * dma_abs) / ma2;
  };
  double dsx = 0, dtx = 0, dsy = 0, dty = 0;
  face_derivative(dx, dsx, dtx);
  face_derivative(dy, dsy, dty);
  const double w = image.width, h = image.height;
  const double rx2 = (dsx * w) * (dsx * w) + (dtx * h) * (dtx * h);
  const double ry2 = (dsy * w) * (dsy * w) + (dty * h) * (dty * h);
  return lambda_from_squared_rho(rx2, ry2);
}

std::array<double, 4> sample(const TextureImage& image, const SamplerState& sampler,
                             const std::array<double, 3>& coordinate, double lod) {
  if (image.levels.empty()) return {0, 0, 0, 0};

  // A NaN lod fails "lod > 0" and so magnifies from level 0, as in llvmpipe.
  const bool magnify = !(lod > 0);
  const Filter filter = magnify ? sampler.mag_filter : sampler.min_filter;
  const int last = level_count(image) - 1;

  // Where to sample: a cube map is a 2D face at (s, t), always clamped to the edge.
  // lavapipe filters seamlessly across faces instead (Vulkan cube maps are seamless), so
  // within one texel of a face edge a linear sample here can differ from the GPU's: a
  // known approximation.
  std::array<double, 3> st = coordinate;
  std::array<Address, 3> modes{sampler.address_u, sampler.address_v, sampler.address_w};
  int face = 0;
  if (image.cube) {
    const CubeFace f = select_face(coordinate);
    // llvmpipe's 0.5 / |ma|, 0 when |ma| is 0 (the direction (0,0,0) samples the centre).
    const double abs_ma = std::abs(f.ma);
    const double half_inverse = abs_ma > 0 ? 0.5 / abs_ma : 0.0;
    st = {f.sc * half_inverse + 0.5, f.tc * half_inverse + 0.5, 0};
    modes = {Address::clamp, Address::clamp, Address::clamp};
    face = f.face;
  }
  const auto at_level = [&](int level) { return filter_level(image, sampler, level, face, st, filter, modes); };

  if (magnify || sampler.mip_filter == MipFilter::none || last == 0) return at_level(0);

  // VK spec "Level-of-Detail Operation": d' = min(lambda, q) (lambda > 0 here, base 0).
  const double d = std::min(lod, static_cast<double>(last));
  if (sampler.mip_filter == MipFilter::nearest) {
    // nearest(d') = ceil(d' + 0.5) - 1: rounds halves down (0.5 -> level 0).
    const int level = static_cast<int>(std::ceil(d + 0.5)) - 1;
    return at_level(std::clamp(level, 0, last));
  }
  const double hi = std::floor(d);
  const double delta = d - hi;
  const int level_hi = std::clamp(static_cast<int>(hi), 0, last);
  const int level_lo = std::min(level_hi + 1, last);
  const Rgba a = at_level(level_hi);
  if (delta == 0 || level_lo == level_hi) return a;
  const Rgba b = at_level(level_lo);
  Rgba result;
  for (size_t c = 0; c < 4; ++c) result[c] = (1 - delta) * a[c] + delta * b[c];
  return result;
}

std::array<double, 4> fetch(const TextureImage& image, bool srgb, const std::array<int, 3>& texel, int level) {
  if (level < 0 || level >= static_cast<int>(image.levels.size())) return {0, 0, 0, 0};
  const std::array<int64_t, 3> size = extent(image, level);
  // A cube map's third coordinate is its face.
  const int64_t layers = image.cube ? 6 : size[2];
  const int64_t x = texel[0], y = image.dimensions >= 2 || image.cube ? texel[1] : 0,
                z = image.dimensions >= 3 || image.cube ? texel[2] : 0;
  if (x < 0 || x >= size[0] || y < 0 || y >= size[1] || z < 0 || z >= layers) return {0, 0, 0, 0};
  const auto linear = static_cast<size_t>((z * size[1] + y) * size[0] + x);
  return read_texel(image, image.levels[static_cast<size_t>(level)], linear * image.channels, srgb);
}

std::array<int, 3> level_size(const TextureImage& image, int level) {
  const std::array<int64_t, 3> size = extent(image, level);
  const auto narrow = [](int64_t v) { return static_cast<int>(std::min<int64_t>(v, INT_MAX)); };
  return {narrow(size[0]), narrow(size[1]), narrow(size[2])};
}

int level_count(const TextureImage& image) {
  return std::max(1, static_cast<int>(std::min<size_t>(image.levels.size(), INT_MAX)));
}

}  // namespace twin
