// Environment maps (sh/EnvironmentMap.h): the two layouts' geometry, reading and writing
// through OpenImageIO, errors as values, and the analytic sky projected from files.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "TempDir.h"
#include "sh/Basis.h"
#include "sh/EnvironmentMap.h"
#include "sh/Lights.h"
#include "sh/Projection.h"
#include "sh/Sampling.h"

namespace sh {
namespace {

using std::numbers::pi;
using shaderbed::test::TempDir;

double distance(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b); }

std::vector<glm::dvec3> uniform_latlong_directions(int count) {
  std::mt19937_64 engine(99);
  auto uniform = [&] { return double(engine() >> 11) * 0x1.0p-53; };
  std::vector<glm::dvec3> directions;
  for (int i = 0; i < count; ++i)
    directions.push_back(latlong_direction({uniform(), std::acos(1 - 2 * uniform()) / pi}));
  return directions;
}

// ---- geometry --------------------------------------------------------------------------------

TEST(EnvironmentMapLayout, LatLongIsTheBooksAngles) {
  EXPECT_LT(distance(latlong_direction({0.0, 0.0}), {0, 0, 1}), 1e-15);   // top row: zenith
  EXPECT_LT(distance(latlong_direction({0.0, 0.5}), {1, 0, 0}), 1e-15);   // left edge: phi = 0
  EXPECT_LT(distance(latlong_direction({0.25, 0.5}), {0, 1, 0}), 1e-15);  // phi = pi/2: +y
  for (const glm::dvec3& d : uniform_latlong_directions(100))
    EXPECT_LT(distance(latlong_direction(latlong_coordinates(d)), d), 1e-14);
}

TEST(EnvironmentMapLayout, AngularIsDebevecsProbeInTheSceneFrame) {
  // Centre: the probe's (scene's) +z, which is SH -y; up: scene +y = SH +z; right: scene +x.
  EXPECT_LT(distance(angular_direction({0, 0}), to_sh_frame({0, 0, 1})), 1e-15);
  EXPECT_LT(distance(angular_direction({0, 0.5}), to_sh_frame({0, 1, 0})), 1e-15);
  EXPECT_LT(distance(angular_direction({0.5, 0}), to_sh_frame({1, 0, 0})), 1e-15);
  EXPECT_LT(distance(angular_direction({-1, 0}), to_sh_frame({0, 0, -1})), 1e-15);  // the rim: backward
  // Debevec's formula directly: D = (D_x, D_y, D_z) at (D_x r, D_y r), r = acos(D_z)/(pi |D_xy|).
  const glm::dvec3 d = glm::normalize(glm::dvec3(0.3, -0.4, 0.5));
  const double r = std::acos(d.z) / (pi * std::hypot(d.x, d.y));
  const glm::dvec2 uv = angular_coordinates(to_sh_frame(d));
  EXPECT_NEAR(uv.x, d.x * r, 1e-15);
  EXPECT_NEAR(uv.y, d.y * r, 1e-15);
  for (const glm::dvec3& w : uniform_latlong_directions(100))
    EXPECT_LT(distance(angular_direction(angular_coordinates(w)), w), 1e-13);
}

TEST(EnvironmentMapLayout, LookupAtAPixelCentreIsThePixel) {
  const int w = 16, h = 8;
  std::vector<glm::vec3> pixels(w * h);
  for (int i = 0; i < w * h; ++i) pixels[i] = glm::vec3(float(i), float(i % 7), 1.0f);
  const EnvironmentMap latlong = EnvironmentMap::from_pixels(MapLayout::latlong, w, h, pixels).value();
  EXPECT_LT(distance(latlong.lookup(latlong_direction({(5 + 0.5) / w, (3 + 0.5) / h})), latlong.pixel(5, 3)), 1e-9);
  // Wraps in phi: half-way between the last column and the first.
  EXPECT_LT(distance(latlong.lookup(latlong_direction({0.0, (3 + 0.5) / h})),
                     0.5 * (latlong.pixel(0, 3) + latlong.pixel(w - 1, 3))),
            1e-9);
  std::vector<glm::vec3> square(64);
  for (int i = 0; i < 64; ++i) square[i] = glm::vec3(float(i));
  const EnvironmentMap angular = EnvironmentMap::from_pixels(MapLayout::angular, 8, 8, square).value();
  // Pixel (6, 1): u = 2 (6.5)/8 - 1, v = 1 - 2 (1.5)/8.
  EXPECT_LT(distance(angular.lookup(angular_direction({2 * 6.5 / 8 - 1, 1 - 2 * 1.5 / 8})), angular.pixel(6, 1)), 1e-9);
}

// ---- files -----------------------------------------------------------------------------------

// The analytic sky through a file: written at pixel centres, read, looked up bilinearly.
// Bilinear interpolation errs by -(h^2/2) s(1-s) f'' across a cell, -(h^2/12) f'' on
// average; projected onto y_i (with a sample set finer than the pixels) the oscillating
// part cancels and two integrations by parts move both derivatives from the sharp sun onto
// the smooth y_i and the layout's area element. With |y_l^m| <= sqrt((2l+1)/(4 pi)) and
// second derivatives of y_l^m up to about (l+1)^2 |y|, per direction, in two directions,
// and a factor 2 for the parameter plane's area against the sphere's, this gives
//   |c_file - c_exact| <~ (h^2/3) bands^2 y_max integral(|f|),
// an estimate of the leading O(h^2) term (not a strict bound), h the map's angular pitch.
double tolerance(double h, int bands, double integral) {
  const double y_max = std::sqrt((2 * bands - 1) / (4 * pi));
  return h * h / 3 * bands * bands * y_max * integral;
}

TEST(EnvironmentMapFile, SkyReadBackProjectsLikeTheAnalyticSky) {
  const TempDir dir("sh_environment");
  const SkyLight sky;
  const int bands = 5;
  // 256 x 512 Gauss-Legendre nodes: finer than either map's pixels.
  const SampleSet set(gauss_legendre_samples(256, 512), bands);
  const auto direct = project_rgb([&](const glm::dvec3& w) { return sky(w); }, set);
  double integral = 0;  // of the brightest channel, the red
  for (const Sample& s : set.samples()) integral += s.weight * sky(s.direction).r;

  const std::string latlong_path = dir / "sky_latlong.exr", angular_path = dir / "sky_angular.exr";
  ASSERT_TRUE(write_sky_latlong(latlong_path, 512, 256, sky));
  ASSERT_TRUE(
      write_environment(angular_path, MapLayout::angular, 512, 512, [&](const glm::dvec3& w) { return sky(w); }));

  struct Case {
    std::string path;
    MapLayout layout;
    double h;  // angular pitch: lat-long pi / H; angular 2 pi / S (a unit of u is pi radians)
  };
  for (const Case& c :
       {Case{latlong_path, MapLayout::latlong, pi / 256}, Case{angular_path, MapLayout::angular, 2 * pi / 512}}) {
    const auto map = EnvironmentMap::read(c.path, c.layout);
    ASSERT_TRUE(map) << map.error();
    const auto from_file = project_rgb([&](const glm::dvec3& w) { return map->lookup(w); }, set);
    const double allowed = tolerance(c.h, bands, integral);
    double worst = 0;
    for (int i = 0; i < coefficient_count(bands); ++i) worst = std::max(worst, distance(from_file[i], direct[i]));
    EXPECT_LT(worst, allowed) << c.path;
    std::printf("%s: max |c_file - c_analytic| = %.2e (tolerance %.2e)\n", c.path.c_str(), worst, allowed);
  }

  // Away from the sun the sky is a + b z + c z^2, and along theta (phi does not matter)
  // |d^2/dtheta^2| <= |b| + 2|c|: a strict pointwise bound (h^2/8)(|b| + 2|c|) for the
  // lat-long map, plus float rounding.
  const auto latlong = EnvironmentMap::read(latlong_path, MapLayout::latlong).value();
  const glm::dvec3 b = 0.5 * (sky.zenith - sky.ground), cz = 0.5 * (sky.zenith + sky.ground) - sky.horizon;
  const double h = pi / 256;
  for (const glm::dvec3& w : uniform_latlong_directions(2000)) {
    if (std::acos(glm::dot(w, sky.sun_direction)) < sky.sun_radius + 2 * h) continue;
    const glm::dvec3 error = glm::abs(latlong.lookup(w) - sky(w));
    const glm::dvec3 bound = h * h / 8 * (glm::abs(b) + 2.0 * glm::abs(cz)) + 1e-6;
    EXPECT_LE(error.r, bound.r);
    EXPECT_LE(error.g, bound.g);
    EXPECT_LE(error.b, bound.b);
  }
}

TEST(EnvironmentMapFile, RadianceHdrReadsBackWithinRgbePrecision) {
  const TempDir dir("sh_environment");
  const SkyLight sky;
  const std::string path = dir / "sky.hdr";
  ASSERT_TRUE(write_environment(path, MapLayout::latlong, 64, 32, [&](const glm::dvec3& w) { return sky(w); }));
  const auto map = EnvironmentMap::read(path, MapLayout::latlong);
  ASSERT_TRUE(map) << map.error();
  ASSERT_EQ(map->width(), 64);
  ASSERT_EQ(map->height(), 32);
  // RGBE: an 8-bit mantissa shared under the largest channel's exponent.
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) {
      const glm::dvec3 exact = sky(latlong_direction({(x + 0.5) / 64, (y + 0.5) / 32}));
      const double largest = std::max({exact.r, exact.g, exact.b});
      EXPECT_LE(distance(map->pixel(x, y), exact), largest / 64) << x << " " << y;
    }
}

TEST(EnvironmentMapFile, ErrorsNameTheFileAndTheProblem) {
  const TempDir dir("sh_environment");
  const auto missing = EnvironmentMap::read(dir / "nothing.exr", MapLayout::latlong);
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("nothing.exr"), std::string::npos);
  EXPECT_NE(missing.error().find("no such file"), std::string::npos);

  const std::string garbage = dir.write("garbage.exr", "this is not an image");
  const auto unreadable = EnvironmentMap::read(garbage, MapLayout::latlong);
  ASSERT_FALSE(unreadable);
  EXPECT_NE(unreadable.error().find("garbage.exr"), std::string::npos);
  EXPECT_NE(unreadable.error().find("unreadable"), std::string::npos);

  const std::string wide = dir / "wide.exr";
  ASSERT_TRUE(write_environment(wide, MapLayout::latlong, 8, 4, [](const glm::dvec3&) { return glm::dvec3(1); }));
  EXPECT_TRUE(EnvironmentMap::read(wide, MapLayout::latlong));
  const auto not_square = EnvironmentMap::read(wide, MapLayout::angular);
  ASSERT_FALSE(not_square);
  EXPECT_NE(not_square.error().find("square"), std::string::npos);
  EXPECT_NE(not_square.error().find("8x4"), std::string::npos);

  EXPECT_FALSE(
      write_environment(dir / "a.exr", MapLayout::angular, 8, 4, [](const glm::dvec3&) { return glm::dvec3(1); }));
  EXPECT_FALSE(write_sky_latlong(dir.path() / "no_such_folder" / "sky.exr", 8, 4));
  EXPECT_FALSE(EnvironmentMap::from_pixels(MapLayout::latlong, 4, 4, std::vector<glm::vec3>(15)));

  // This OpenImageIO writes no volume files (TIFF, EXR and FITS refuse depth > 1), so the
  // check that read() applies to the image's spec is exercised directly.
  const auto volume =
      check_image_shape("volume.tif", {.width = 4, .height = 4, .depth = 2, .channels = 3}, MapLayout::latlong);
  ASSERT_FALSE(volume);
  EXPECT_NE(volume.error().find("volume.tif: not a 2D image"), std::string::npos) << volume.error();
  EXPECT_FALSE(
      check_image_shape("deep.exr", {.width = 4, .height = 4, .channels = 3, .deep = true}, MapLayout::latlong));
  EXPECT_FALSE(check_image_shape("empty.exr", {.width = 0, .height = 4, .channels = 3}, MapLayout::latlong));
  EXPECT_TRUE(check_image_shape("fine.exr", {.width = 8, .height = 8, .channels = 1}, MapLayout::angular));
}

TEST(EnvironmentMapFile, GreyAndAlphaImages) {
  const TempDir dir("sh_environment");
  for (int channels : {1, 2, 4}) {
    const std::string path = dir / ("c" + std::to_string(channels) + ".exr");
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    const OIIO::ImageSpec spec(4, 2, channels, OIIO::TypeDesc::FLOAT);
    std::vector<float> data(4 * 2 * channels);
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = float(i % channels + 1);
    ASSERT_TRUE(out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, data.data()) && out->close());
    const auto map = EnvironmentMap::read(path, MapLayout::latlong);
    ASSERT_TRUE(map) << map.error();
    const glm::dvec3 expected = channels >= 3 ? glm::dvec3(1, 2, 3) : glm::dvec3(1);
    EXPECT_EQ(map->pixel(1, 1), expected) << channels;
  }
}

}  // namespace
}  // namespace sh
