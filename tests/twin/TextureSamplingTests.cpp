// CPU texture sampling with Vulkan's rules: filters, address modes, sRGB, mips, LOD, cube faces, fetch.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "twin/TextureSampling.h"

namespace twin {
namespace {

using Rgba = std::array<double, 4>;
constexpr double kEps = 1e-12;

// A texture that owns its texel data; the image's spans point into `data`, whose
// buffers keep their address when the whole object is moved.
struct OwnedTexture {
  std::vector<std::vector<float>> data;
  TextureImage image;
};

OwnedTexture make_texture(uint32_t dimensions, uint32_t w, uint32_t h, uint32_t d, uint32_t channels,
                          std::vector<std::vector<float>> levels, bool cube = false) {
  OwnedTexture t{std::move(levels), {}};
  t.image.dimensions = dimensions;
  t.image.cube = cube;
  t.image.width = w, t.image.height = h, t.image.depth = d;
  t.image.channels = channels;
  for (const auto& level : t.data) t.image.levels.emplace_back(level);
  return t;
}

// Four RGBA texels in a row with red = 10, 20, 30, 40 (green, blue 0; alpha 1).
OwnedTexture row_of_four() {
  return make_texture(1, 4, 1, 1, 4, {{10, 0, 0, 1, 20, 0, 0, 1, 30, 0, 0, 1, 40, 0, 0, 1}});
}

SamplerState sampler_with(Filter filter, Address address = Address::clamp) {
  SamplerState s;
  s.min_filter = s.mag_filter = filter;
  s.address_u = s.address_v = s.address_w = address;
  return s;
}

void expect_rgba(const Rgba& actual, const Rgba& expected, double eps = kEps) {
  for (size_t c = 0; c < 4; ++c) EXPECT_NEAR(actual[c], expected[c], eps) << "channel " << c;
}

double red(const TextureImage& image, const SamplerState& s, std::array<double, 3> coordinate, double lod = 0) {
  return sample(image, s, coordinate, lod)[0];
}

TEST(TextureSampling, NearestAndLinearOnARowOfFour) {
  // One channel: 0, 0.25, 0.5, 1.
  const auto t = make_texture(1, 4, 1, 1, 1, {{0.0f, 0.25f, 0.5f, 1.0f}});
  const auto nearest = sampler_with(Filter::nearest), linear = sampler_with(Filter::linear);
  // s = 0.3: u = 1.2 -> texel 1.
  expect_rgba(sample(t.image, nearest, {0.3, 0, 0}, 0), {0.25, 0, 0, 1});
  // u = 2 exactly -> texel 2 (floor, not round).
  EXPECT_NEAR(red(t.image, nearest, {0.5, 0, 0}), 0.5, kEps);
  // s = 0.3: u' = 1.2 - 0.5 = 0.7 -> texels 0, 1 with alpha 0.7: 0.3 * 0 + 0.7 * 0.25 = 0.175.
  expect_rgba(sample(t.image, linear, {0.3, 0, 0}, 0), {0.175, 0, 0, 1});
  // s = 0.5: u' = 1.5 -> half of texel 1 and 2: 0.375.
  EXPECT_NEAR(red(t.image, linear, {0.5, 0, 0}), 0.375, kEps);
  // s = 0.625: u' = 2 -> texel 2 alone.
  EXPECT_NEAR(red(t.image, linear, {0.625, 0, 0}), 0.5, kEps);
  // A 1D texture ignores y and z.
  EXPECT_NEAR(red(t.image, linear, {0.3, 7.7, -3.1}), 0.175, kEps);
}

TEST(TextureSampling, NearestAndLinearOnFourByFour) {
  // Texel (x, y) = (x, y, x + 10 y, 1): bilinear filtering of a linear function is exact.
  std::vector<float> texels;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) texels.insert(texels.end(), {float(x), float(y), float(x + 10 * y), 1.0f});
  const auto t = make_texture(2, 4, 4, 1, 4, {texels});
  // (0.3, 0.6): u = 1.2, v = 2.4 -> nearest texel (1, 2).
  expect_rgba(sample(t.image, sampler_with(Filter::nearest), {0.3, 0.6, 0}, 0), {1, 2, 21, 1});
  // Linear: u' = 0.7, v' = 1.9 -> (0.7, 1.9, 0.7 + 19, 1).
  expect_rgba(sample(t.image, sampler_with(Filter::linear), {0.3, 0.6, 0}, 0), {0.7, 1.9, 19.7, 1});
  // A 2D texture ignores z.
  expect_rgba(sample(t.image, sampler_with(Filter::linear), {0.3, 0.6, 42}, 0), {0.7, 1.9, 19.7, 1});
  // Texel (3, 0) at the corner of the texel grid: x fastest in memory.
  expect_rgba(sample(t.image, sampler_with(Filter::nearest), {0.9, 0.1, 0}, 0), {3, 0, 3, 1});
}

TEST(TextureSampling, TrilinearOnTwoCubed) {
  // Texel (x, y, z) = x + 2y + 4z; the centre is the average of all eight: 3.5.
  std::vector<float> texels;
  for (int i = 0; i < 8; ++i) texels.push_back(float(i));
  const auto t = make_texture(3, 2, 2, 2, 1, {texels});
  EXPECT_NEAR(red(t.image, sampler_with(Filter::linear), {0.5, 0.5, 0.5}), 3.5, kEps);
  // Nearest (0.8, 0.2, 0.8) -> (1, 0, 1) = 5.
  EXPECT_NEAR(red(t.image, sampler_with(Filter::nearest), {0.8, 0.2, 0.8}), 5, kEps);
}

TEST(TextureSampling, WrapRepeatsAtNegativeCoordinates) {
  const auto t = row_of_four();
  const auto nearest = sampler_with(Filter::nearest, Address::wrap);
  // u = -0.4 -> i = -1 -> 3.
  EXPECT_NEAR(red(t.image, nearest, {-0.1, 0, 0}), 40, kEps);
  // u = -4.4 -> i = -5 -> 3.
  EXPECT_NEAR(red(t.image, nearest, {-1.1, 0, 0}), 40, kEps);
  // u = 5.2 -> i = 5 -> 1.
  EXPECT_NEAR(red(t.image, nearest, {1.3, 0, 0}), 20, kEps);
  // Linear at s = 0: u' = -0.5 -> texels -1 (= 3) and 0, half each: (40 + 10) / 2.
  EXPECT_NEAR(red(t.image, sampler_with(Filter::linear, Address::wrap), {0, 0, 0}), 25, kEps);
}

TEST(TextureSampling, MirrorReflectsAtEachEdge) {
  const auto t = row_of_four();
  const auto nearest = sampler_with(Filter::nearest, Address::mirror);
  // i = -1: -1 mod 8 = 7 -> 2*4 - 1 - 7 = 0.
  EXPECT_NEAR(red(t.image, nearest, {-0.1, 0, 0}), 10, kEps);
  // u = -1.2 -> i = -2 -> 6 -> 1.
  EXPECT_NEAR(red(t.image, nearest, {-0.3, 0, 0}), 20, kEps);
  // u = -4.4 -> i = -5 -> 3 -> 3 (mirrored twice).
  EXPECT_NEAR(red(t.image, nearest, {-1.1, 0, 0}), 40, kEps);
  // u = 4.4 -> i = 4 -> 3; u = 6.4 -> i = 6 -> 1.
  EXPECT_NEAR(red(t.image, nearest, {1.1, 0, 0}), 40, kEps);
  EXPECT_NEAR(red(t.image, nearest, {1.6, 0, 0}), 20, kEps);
  // Linear at s = 0: texels -1 (= 0) and 0 -> 10; at u = -0.75 (s = -0.1875): u' = -1.25,
  // texels -2 (= 1) and -1 (= 0), alpha 0.75: 0.25 * 20 + 0.75 * 10 = 12.5.
  const auto linear = sampler_with(Filter::linear, Address::mirror);
  EXPECT_NEAR(red(t.image, linear, {0, 0, 0}), 10, kEps);
  EXPECT_NEAR(red(t.image, linear, {-0.1875, 0, 0}), 12.5, kEps);
}

TEST(TextureSampling, ClampHoldsTheEdgeTexel) {
  const auto t = row_of_four();
  const auto nearest = sampler_with(Filter::nearest, Address::clamp);
  EXPECT_NEAR(red(t.image, nearest, {-0.1, 0, 0}), 10, kEps);
  EXPECT_NEAR(red(t.image, nearest, {-5, 0, 0}), 10, kEps);
  EXPECT_NEAR(red(t.image, nearest, {1.5, 0, 0}), 40, kEps);
  // Linear at s = 0: texels -1 (= 0) and 0 -> 10; at s = 1: texels 3 and 4 (= 3) -> 40.
  const auto linear = sampler_with(Filter::linear, Address::clamp);
  EXPECT_NEAR(red(t.image, linear, {0, 0, 0}), 10, kEps);
  EXPECT_NEAR(red(t.image, linear, {1, 0, 0}), 40, kEps);
}

TEST(TextureSampling, BorderTexelsTakePartInFiltering) {
  const auto t = row_of_four();
  auto nearest = sampler_with(Filter::nearest, Address::border);
  nearest.border = {2, 4, 6, 8};
  expect_rgba(sample(t.image, nearest, {-0.1, 0, 0}, 0), {2, 4, 6, 8});
  expect_rgba(sample(t.image, nearest, {1.0, 0, 0}, 0), {2, 4, 6, 8});
  expect_rgba(sample(t.image, nearest, {0.9, 0, 0}, 0), {40, 0, 0, 1});
  // Linear at s = 0: half border, half texel 0: (1 + 5, 2, 3, 4 + 0.5).
  auto linear = nearest;
  linear.min_filter = linear.mag_filter = Filter::linear;
  expect_rgba(sample(t.image, linear, {0, 0, 0}, 0), {6, 2, 3, 4.5});
  // Border on v only: a 2D texture sampled just above its top row, nearest.
  const auto t2 = make_texture(2, 1, 1, 1, 4, {{1, 1, 1, 1}});
  auto v_border = sampler_with(Filter::nearest, Address::clamp);
  v_border.address_v = Address::border;
  v_border.border = {0.5, 0.5, 0.5, 0.5};
  expect_rgba(sample(t2.image, v_border, {-3, -0.2, 0}, 0), {0.5, 0.5, 0.5, 0.5});
  expect_rgba(sample(t2.image, v_border, {-3, 0.5, 0}, 0), {1, 1, 1, 1});
}

TEST(TextureSampling, BorderOfOneChannelImageReplacesOnlyRed) {
  // Like llvmpipe, the format's missing channels stay (0, 0, 1).
  const auto t = make_texture(1, 2, 1, 1, 1, {{0.5f, 0.5f}});
  auto s = sampler_with(Filter::nearest, Address::border);
  s.border = {0.25, 0.75, 0.75, 0.75};
  expect_rgba(sample(t.image, s, {-0.5, 0, 0}, 0), {0.25, 0, 0, 1});
}

TEST(TextureSampling, BorderIsClampedForNormalisedImages) {
  auto t = row_of_four();
  t.image.unorm8 = true;
  auto s = sampler_with(Filter::nearest, Address::border);
  s.border = {2, -1, 0.5, 1};
  expect_rgba(sample(t.image, s, {-0.5, 0, 0}, 0), {1, 0, 0.5, 1});
}

TEST(TextureSampling, SrgbIsDecodedPerTexelBeforeFiltering) {
  // Texels (0, 0, 0, 0.5) and (1, 1, 1, 0.5), sRGB.
  const auto t = make_texture(1, 2, 1, 1, 4, {{0, 0, 0, 0.5f, 1, 1, 1, 0.5f}});
  auto s = sampler_with(Filter::linear);
  s.srgb = true;
  // Midway: decode(0) = 0, decode(1) = 1, averaged: 0.5. Decoding the average instead
  // would give decode(0.5) = ((0.5 + 0.055) / 1.055)^2.4 = 0.2140.
  const Rgba mid = sample(t.image, s, {0.5, 0, 0}, 0);
  expect_rgba(mid, {0.5, 0.5, 0.5, 0.5});
  EXPECT_GT(std::abs(mid[0] - std::pow(0.555 / 1.055, 2.4)), 0.25);

  // Each branch of the decode; alpha is never decoded.
  const auto u = make_texture(1, 2, 1, 1, 4, {{0.5f, 0.04f, 1, 0.5f, 0, 0, 0, 1}});
  auto n = sampler_with(Filter::nearest);
  n.srgb = true;
  expect_rgba(sample(u.image, n, {0.25, 0, 0}, 0),
              {std::pow((0.5 + 0.055) / 1.055, 2.4), double(0.04f) / 12.92, 1, 0.5}, 1e-9);
  // Without the flag the values pass through.
  expect_rgba(sample(u.image, sampler_with(Filter::nearest), {0.25, 0, 0}, 0), {0.5, double(0.04f), 1, 0.5});
}

TEST(TextureSampling, OneChannelExpandsToRedZeroZeroOne) {
  const auto t = make_texture(2, 1, 1, 1, 1, {{0.625f}});
  expect_rgba(sample(t.image, sampler_with(Filter::linear), {0.5, 0.5, 0}, 0), {0.625, 0, 0, 1});
  expect_rgba(fetch(t.image, false, {0, 0, 0}, 0), {0.625, 0, 0, 1});
}

// Three levels of a 4x4 texture, each one constant colour: red, green, blue.
OwnedTexture three_level_texture() {
  const auto constant = [](int texels, std::array<float, 4> c) {
    std::vector<float> v;
    for (int i = 0; i < texels; ++i) v.insert(v.end(), c.begin(), c.end());
    return v;
  };
  return make_texture(2, 4, 4, 1, 4, {constant(16, {1, 0, 0, 1}), constant(4, {0, 1, 0, 1}), constant(1, {0, 0, 1, 1})});
}

TEST(TextureSampling, NearestMipRoundsTheLod) {
  const auto t = three_level_texture();
  auto s = sampler_with(Filter::linear);
  s.mip_filter = MipFilter::nearest;
  const std::array<double, 3> c{0.3, 0.7, 0};
  expect_rgba(sample(t.image, s, c, -2), {1, 0, 0, 1});
  expect_rgba(sample(t.image, s, c, 0.4), {1, 0, 0, 1});
  // ceil(0.5 + 0.5) - 1 = 0: halves round down.
  expect_rgba(sample(t.image, s, c, 0.5), {1, 0, 0, 1});
  expect_rgba(sample(t.image, s, c, 0.6), {0, 1, 0, 1});
  expect_rgba(sample(t.image, s, c, 1.4), {0, 1, 0, 1});
  expect_rgba(sample(t.image, s, c, 1.6), {0, 0, 1, 1});
  // Beyond the last level: the last level.
  expect_rgba(sample(t.image, s, c, 9), {0, 0, 1, 1});
  expect_rgba(sample(t.image, s, c, std::numeric_limits<double>::infinity()), {0, 0, 1, 1});
}

TEST(TextureSampling, LinearMipBlendsAdjacentLevels) {
  const auto t = three_level_texture();
  auto s = sampler_with(Filter::nearest);
  s.mip_filter = MipFilter::linear;
  const std::array<double, 3> c{0.3, 0.7, 0};
  expect_rgba(sample(t.image, s, c, 0.25), {0.75, 0.25, 0, 1});
  expect_rgba(sample(t.image, s, c, 1.5), {0, 0.5, 0.5, 1});
  expect_rgba(sample(t.image, s, c, 2), {0, 0, 1, 1});
  expect_rgba(sample(t.image, s, c, 7.3), {0, 0, 1, 1});
  expect_rgba(sample(t.image, s, c, -1), {1, 0, 0, 1});
}

TEST(TextureSampling, NoMipFilterAlwaysUsesLevelZero) {
  const auto t = three_level_texture();
  auto s = sampler_with(Filter::linear);
  expect_rgba(sample(t.image, s, {0.5, 0.5, 0}, 2), {1, 0, 0, 1});
}

TEST(TextureSampling, OnlyOneLevelClampsToIt) {
  auto t = row_of_four();
  auto s = sampler_with(Filter::nearest);
  s.mip_filter = MipFilter::linear;
  EXPECT_NEAR(red(t.image, s, {0.3, 0, 0}, 3.5), 20, kEps);
  s.mip_filter = MipFilter::nearest;
  EXPECT_NEAR(red(t.image, s, {0.3, 0, 0}, 3.5), 20, kEps);
}

TEST(TextureSampling, MagnificationAtLodZeroAndBelowMinificationAbove) {
  const auto t = make_texture(1, 4, 1, 1, 1, {{0.0f, 0.25f, 0.5f, 1.0f}});
  SamplerState s;
  s.mag_filter = Filter::nearest;
  s.min_filter = Filter::linear;
  // s = 0.3: nearest 0.25, linear 0.175.
  EXPECT_NEAR(red(t.image, s, {0.3, 0, 0}, 0), 0.25, kEps);
  EXPECT_NEAR(red(t.image, s, {0.3, 0, 0}, -3), 0.25, kEps);
  EXPECT_NEAR(red(t.image, s, {0.3, 0, 0}, 0.01), 0.175, kEps);
  // NaN lod magnifies from level 0 (it fails lod > 0).
  EXPECT_NEAR(red(t.image, s, {0.3, 0, 0}, std::nan("")), 0.25, kEps);
}

TEST(TextureSampling, LinearFilterOnASmallerLevelUsesThatLevelsSize) {
  // Level 1 of a 4x1 row is 2x1 with red 0 and 1: at s = 0.5, u' = 0.5 -> 0.5.
  const auto t = make_texture(1, 4, 1, 1, 1, {{9, 9, 9, 9}, {0, 1}});
  auto s = sampler_with(Filter::linear);
  s.mip_filter = MipFilter::nearest;
  EXPECT_NEAR(red(t.image, s, {0.5, 0, 0}, 1), 0.5, kEps);
  // s = 0.3 on two texels: u' = 0.1 -> 0.1.
  EXPECT_NEAR(red(t.image, s, {0.3, 0, 0}, 1), 0.1, kEps);
}

TEST(TextureSampling, ImplicitLodOfScaledDerivatives) {
  const auto t = make_texture(2, 8, 8, 1, 1, {std::vector<float>(64, 0)});
  // One texel per pixel: lambda 0.
  EXPECT_NEAR(implicit_lod(t.image, {0.5, 0.5, 0}, {{1.0 / 8, 0, 0}, {0, 0, 0}}), 0, kEps);
  EXPECT_NEAR(implicit_lod(t.image, {0.5, 0.5, 0}, {{0, 0, 0}, {0, 1.0 / 8, 0}}), 0, kEps);
  EXPECT_NEAR(implicit_lod(t.image, {0.5, 0.5, 0}, {{1.0 / 4, 0, 0}, {0, 0, 0}}), 1, kEps);
  // The larger of the two: |dy| = 4 texels -> 2.
  EXPECT_NEAR(implicit_lod(t.image, {0.5, 0.5, 0}, {{1.0 / 8, 0, 0}, {0, 0.5, 0}}), 2, kEps);
  // The length, not the largest component: |(1, 1)| = sqrt 2 -> 0.5.
  EXPECT_NEAR(implicit_lod(t.image, {0.5, 0.5, 0}, {{1.0 / 8, 1.0 / 8, 0}, {0, 0, 0}}), 0.5, kEps);
  // A 2D texture ignores z derivatives; no change at all magnifies.
  EXPECT_LT(implicit_lod(t.image, {0.5, 0.5, 0}, {{0, 0, 5}, {0, 0, 5}}), -1e300);
  EXPECT_LT(implicit_lod(t.image, {0.5, 0.5, 0}, {}), -1e300);
  // Non-square: x scaled by the width (16), y by the height (2).
  const auto wide = make_texture(2, 16, 2, 1, 1, {std::vector<float>(32, 0)});
  EXPECT_NEAR(implicit_lod(wide.image, {0, 0, 0}, {{1.0 / 16, 0, 0}, {0, 1.0, 0}}), 1, kEps);
  // 1D ignores y; 3D scales z by the depth.
  const auto line = make_texture(1, 8, 1, 1, 1, {std::vector<float>(8, 0)});
  EXPECT_LT(implicit_lod(line.image, {0, 0, 0}, {{0, 1, 0}, {0, 1, 0}}), -1e300);
  const auto box = make_texture(3, 2, 2, 4, 1, {std::vector<float>(16, 0)});
  EXPECT_NEAR(implicit_lod(box.image, {0, 0, 0}, {{0, 0, 1.0}, {0, 0, 0}}), 2, kEps);
}

// A cube map with 2x2 faces, texel (x, y) of face f = 10 f + x + 2 y, and a 1x1 level 1
// whose face f is 100 + f.
OwnedTexture numbered_cube() {
  std::vector<float> level0, level1;
  for (int f = 0; f < 6; ++f) {
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) level0.push_back(float(10 * f + x + 2 * y));
    level1.push_back(float(100 + f));
  }
  return make_texture(2, 2, 2, 1, 1, {level0, level1}, true);
}

TEST(TextureSampling, CubeFaceForEachAxis) {
  const auto t = numbered_cube();
  const auto s = sampler_with(Filter::nearest);
  // Centre of each face: s = t = 0.5 -> texel (1, 1) = 10 f + 3.
  const std::array<std::array<double, 3>, 6> axes{{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
  for (int f = 0; f < 6; ++f) EXPECT_NEAR(red(t.image, s, axes[f]), 10 * f + 3, kEps) << "face " << f;
  // Not normalised: only the direction counts.
  EXPECT_NEAR(red(t.image, s, {0, -7, 0}), 33, kEps);
}

TEST(TextureSampling, CubeFaceCoordinatesFollowTheSpecTable) {
  const auto t = numbered_cube();
  const auto s = sampler_with(Filter::nearest);
  // Directions with sc = +0.5, tc = -0.5 on each face: s = 0.75, t = 0.25 -> texel
  // (1, 0) = 10 f + 1. +X: sc = -rz, tc = -ry; -X: sc = rz, tc = -ry; +Y: sc = rx,
  // tc = rz; -Y: sc = rx, tc = -rz; +Z: sc = rx, tc = -ry; -Z: sc = -rx, tc = -ry.
  const std::array<std::array<double, 3>, 6> directions{
      {{1, 0.5, -0.5}, {-1, 0.5, 0.5}, {0.5, 1, -0.5}, {0.5, -1, 0.5}, {0.5, 0.5, 1}, {-0.5, 0.5, -1}}};
  for (int f = 0; f < 6; ++f) EXPECT_NEAR(red(t.image, s, directions[f]), 10 * f + 1, kEps) << "face " << f;
}

TEST(TextureSampling, CubeTiesPreferZThenY) {
  const auto t = numbered_cube();
  const auto s = sampler_with(Filter::nearest);
  const auto face_of = [&](std::array<double, 3> d) { return int(red(t.image, s, d)) / 10; };
  EXPECT_EQ(face_of({1, 1, 1}), 4);
  EXPECT_EQ(face_of({1, -1, -1}), 5);
  EXPECT_EQ(face_of({-1, 0, 1}), 4);
  EXPECT_EQ(face_of({1, 1, 0}), 2);
  EXPECT_EQ(face_of({-1, -1, 0}), 3);
  EXPECT_EQ(face_of({1, 0.999, 0.999}), 0);
}

TEST(TextureSampling, CubeLevelsHoldSixFaces) {
  const auto t = numbered_cube();
  auto s = sampler_with(Filter::linear);
  s.mip_filter = MipFilter::nearest;
  const std::array<std::array<double, 3>, 6> axes{{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
  for (int f = 0; f < 6; ++f) EXPECT_NEAR(red(t.image, s, axes[f], 1), 100 + f, kEps) << "face " << f;
  // Linear at the centre of +Z averages its four texels: 40 + 1.5. Near the corner
  // (s = t = 0.995, u' = 1.49) the taps past the edge clamp to texel (1, 1) = 43: no
  // seamless filtering into the neighbouring faces.
  EXPECT_NEAR(red(t.image, sampler_with(Filter::linear), {0, 0, 1}), 41.5, kEps);
  EXPECT_NEAR(red(t.image, sampler_with(Filter::linear), {0.99, -0.99, 1}), 43, 1e-9);
  expect_rgba(fetch(t.image, false, {0, 0, 3}, 1), {103, 0, 0, 1});
  expect_rgba(fetch(t.image, false, {1, 0, 5}, 0), {51, 0, 0, 1});
  expect_rgba(fetch(t.image, false, {0, 0, 6}, 0), {0, 0, 0, 0});
}

TEST(TextureSampling, CubeImplicitLodUsesTheFaceDerivatives) {
  const auto t = make_texture(2, 8, 8, 1, 1, {std::vector<float>(6 * 64, 0)}, true);
  // +Z at its centre: s = (rx / 1 + 1) / 2, so drx = 1/4 is 1/8 of the face: lambda 0.
  EXPECT_NEAR(implicit_lod(t.image, {0, 0, 1}, {{0.25, 0, 0}, {0, 0, 0}}), 0, kEps);
  EXPECT_NEAR(implicit_lod(t.image, {0, 0, -1}, {{0.25, 0, 0}, {0, 0, 0}}), 0, kEps);
  EXPECT_NEAR(implicit_lod(t.image, {1, 0, 0}, {{0, 0, 0}, {0, 0.5, 0}}), 1, kEps);
  // The quotient term: at (0.5, 0, 1) moving along z by 0.5, s = (0.5 / rz + 1) / 2
  // changes by 0.5 * 0.5 * 0.5 = 1/8 -> 1 texel -> 0.
  EXPECT_NEAR(implicit_lod(t.image, {0.5, 0, 1}, {{0, 0, 0.5}, {0, 0, 0}}), 0, kEps);
  // Moving along the direction itself changes no face coordinate on any face, negative
  // faces included (the derivative of sc / |ma|, not of sc / ma with |ma|).
  const std::array<std::array<double, 3>, 6> directions{
      {{1, 0.5, -0.5}, {-1, 0.5, 0.5}, {0.5, 1, -0.5}, {0.5, -1, 0.5}, {0.5, 0.5, 1}, {-0.5, 0.5, -1}}};
  for (const auto& d : directions) {
    const std::array<double, 3> radial{0.5 * d[0], 0.5 * d[1], 0.5 * d[2]};
    EXPECT_LT(implicit_lod(t.image, d, {radial, radial}), -1e300) << d[0] << " " << d[1] << " " << d[2];
  }
  // Zero direction: no face; magnify rather than divide by zero.
  EXPECT_LT(implicit_lod(t.image, {0, 0, 0}, {{1, 0, 0}, {0, 1, 0}}), -1e300);
}

TEST(TextureSampling, FetchReadsExactTexelsAndZeroOutOfRange) {
  std::vector<float> texels;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) texels.insert(texels.end(), {float(x), float(y), 0.5f, 0.25f});
  const auto t = make_texture(2, 3, 2, 1, 4, {texels, {7, 7, 7, 7}});
  expect_rgba(fetch(t.image, false, {2, 1, 0}, 0), {2, 1, 0.5, 0.25});
  expect_rgba(fetch(t.image, false, {0, 0, 0}, 1), {7, 7, 7, 7});
  for (const auto& xyz : std::array<std::array<int, 3>, 4>{{{-1, 0, 0}, {3, 0, 0}, {0, 2, 0}, {0, -1, 0}}})
    expect_rgba(fetch(t.image, false, xyz, 0), {0, 0, 0, 0});
  expect_rgba(fetch(t.image, false, {1, 0, 0}, 1), {0, 0, 0, 0});
  expect_rgba(fetch(t.image, false, {0, 0, 0}, 2), {0, 0, 0, 0});
  expect_rgba(fetch(t.image, false, {0, 0, 0}, -1), {0, 0, 0, 0});
  // sRGB decode on RGB only.
  expect_rgba(fetch(t.image, true, {1, 1, 0}, 0), {1, std::pow(1.055 / 1.055, 2.4), std::pow(0.555 / 1.055, 2.4), 0.25});
}

TEST(TextureSampling, LevelSizesHalveDownToOne) {
  const auto t = make_texture(2, 5, 3, 1, 1, {std::vector<float>(15, 0), std::vector<float>(2, 0), {0}});
  EXPECT_EQ(level_count(t.image), 3);
  EXPECT_EQ(level_size(t.image, 0), (std::array<int, 3>{5, 3, 1}));
  EXPECT_EQ(level_size(t.image, 1), (std::array<int, 3>{2, 1, 1}));
  EXPECT_EQ(level_size(t.image, 2), (std::array<int, 3>{1, 1, 1}));
  const auto line = make_texture(1, 8, 4, 4, 1, {std::vector<float>(8, 0)});
  EXPECT_EQ(level_size(line.image, 1), (std::array<int, 3>{4, 1, 1}));
  const auto box = make_texture(3, 8, 4, 2, 1, {std::vector<float>(64, 0)});
  EXPECT_EQ(level_size(box.image, 1), (std::array<int, 3>{4, 2, 1}));
  EXPECT_EQ(level_size(box.image, 40), (std::array<int, 3>{1, 1, 1}));
  const auto cube = numbered_cube();
  EXPECT_EQ(level_size(cube.image, 0), (std::array<int, 3>{2, 2, 1}));
  EXPECT_EQ(level_count(cube.image), 2);
  TextureImage empty;
  EXPECT_EQ(level_count(empty), 1);
}

TEST(TextureSampling, NonFiniteAndHugeCoordinatesStayInBounds) {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  const auto row = row_of_four();
  const auto cube = numbered_cube();
  for (Address a : {Address::wrap, Address::mirror, Address::clamp, Address::border})
    for (Filter f : {Filter::nearest, Filter::linear})
      for (double x : {nan, inf, -inf, 1e30, -1e30, 1e300}) {
        const auto s = sampler_with(f, a);
        const Rgba r = sample(row.image, s, {x, x, x}, 0);
        for (double c : r) EXPECT_TRUE(std::isfinite(c)) << x;
        // Texels are 10..40 and the border is 0, so any filtered mix lies in [0, 40].
        EXPECT_TRUE(r[0] >= 0 && r[0] <= 40) << r[0];
        const Rgba c = sample(cube.image, s, {x, 0.5, -x}, 0);
        for (double v : c) EXPECT_TRUE(std::isfinite(v)) << x;
      }
  // NaN coordinate reads texel 0 (nearest, clamp).
  EXPECT_NEAR(red(row.image, sampler_with(Filter::nearest), {nan, 0, 0}), 10, kEps);
  // Implicit LOD of non-finite derivatives magnifies instead of producing NaN.
  EXPECT_LT(implicit_lod(row.image, {0, 0, 0}, {{nan, 0, 0}, {0, 0, 0}}), -1e300);
  EXPECT_LT(implicit_lod(row.image, {0, 0, 0}, {{inf, 0, 0}, {0, 0, 0}}), -1e300);
  EXPECT_LT(implicit_lod(cube.image, {nan, nan, nan}, {{1, 0, 0}, {0, 1, 0}}), -1e300);
}

TEST(TextureSampling, ShortOrMissingDataReadsZeroInsteadOfOutOfBounds) {
  // Level 0 says 4x4 RGBA but holds one texel.
  const auto t = make_texture(2, 4, 4, 1, 4, {{1, 2, 3, 4}});
  expect_rgba(sample(t.image, sampler_with(Filter::nearest), {0.1, 0.1, 0}, 0), {1, 2, 3, 4});
  expect_rgba(sample(t.image, sampler_with(Filter::nearest), {0.9, 0.9, 0}, 0), {0, 0, 0, 0});
  expect_rgba(fetch(t.image, false, {3, 3, 0}, 0), {0, 0, 0, 0});
  TextureImage empty;
  expect_rgba(sample(empty, sampler_with(Filter::linear), {0.5, 0.5, 0}, 0), {0, 0, 0, 0});
  expect_rgba(fetch(empty, false, {0, 0, 0}, 0), {0, 0, 0, 0});
}

}  // namespace
}  // namespace twin
