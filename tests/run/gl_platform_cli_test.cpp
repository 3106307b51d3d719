// --gl-platform and --gl-device through the binary: the default library's GL cells drawn
// on OSMesa and on EGL (surfaceless; Mesa's software device) are bit-identical cell by
// cell, every GL path and the LUT (texture) variants among them; the results record the
// platform the workers drew on; a platform or device that does not exist is bad input
// (exit 2) saying what there is; `devices` lists the EGL devices.
#include <cstring>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ShellCommand.h"
#include "TempDir.h"
#include "run/StoredImages.h"

namespace shaderbed {
namespace {

using test::shaderbed_cli;
using test::TempDir;

constexpr int kCellSize = 24;

struct PlatformRun {
  int status = -1;
  std::string output;
  nlohmann::json results;
};

// The whole default library on GL, on one sphere per cell, its images kept in `images`.
PlatformRun run_library_on(const std::string& platform_args, const TempDir& dir, const std::string& name) {
  const std::string json = dir / (name + ".json");
  auto [status, out] = shaderbed_cli("run " + platform_args + " --backend gl --shape sphere --size " +
                                     std::to_string(kCellSize) + " --repeat 0 --quiet --save-images " +
                                     (dir / (name + "-images")) + " --json " + json);
  PlatformRun run{status, out, {}};
  std::ifstream in(json);
  if (in) run.results = nlohmann::json::parse(in, nullptr, false);
  return run;
}

// Every stored image of `b` is bit for bit the one of `a` with the same id; returns how
// many were compared (0 with a failure when the sets differ).
size_t expect_identical_images(const std::string& a_dir, const std::string& b_dir) {
  auto a = load_stored_run(a_dir, kCellSize);
  auto b = load_stored_run(b_dir, kCellSize);
  EXPECT_TRUE(a && b) << (a ? b.error().to_string() : a.error().to_string());
  if (!a || !b) return 0;
  std::set<std::string> a_ids, b_ids;
  for (const auto& [id, image] : a->images) a_ids.insert(id);
  for (const auto& [id, image] : b->images) b_ids.insert(id);
  EXPECT_EQ(a_ids, b_ids) << "the same cells drew on both platforms";
  size_t compared = 0;
  for (const auto& [id, stored] : a->images) {
    if (!b->images.contains(id)) continue;
    auto image_a = load_stored_image(*a, id, stored.scene);
    auto image_b = load_stored_image(*b, id, b->images.at(id).scene);
    EXPECT_TRUE(image_a && image_b) << id;
    if (!image_a || !image_b) continue;
    EXPECT_EQ(image_a->coverage, image_b->coverage) << id;
    const size_t bytes = image_a->rgba.size() * sizeof(double);
    const bool same = image_a->rgba.size() == image_b->rgba.size() &&
                      std::memcmp(image_a->rgba.data(), image_b->rgba.data(), bytes) == 0;
    EXPECT_TRUE(same) << id << " differs between the platforms";
    ++compared;
  }
  return compared;
}

// What the comparison covered: every GL path, and the LUT variants that sample textures.
void expect_every_gl_path_and_a_texture(const std::string& images_dir) {
  auto run = load_stored_run(images_dir, kCellSize);
  ASSERT_TRUE(run) << run.error().to_string();
  bool native = false, spirv = false, cross = false, lut = false;
  for (const auto& [id, image] : run->images) {
    native |= id.find("/gl/glsl/") != std::string::npos;
    spirv |= id.find("/gl/spirv/") != std::string::npos;
    cross |= id.find("/gl/cross/") != std::string::npos;
    lut |= id.find("/pixel_lut/") != std::string::npos;
  }
  EXPECT_TRUE(native && spirv && cross) << "native " << native << ", spirv " << spirv << ", cross " << cross;
  EXPECT_TRUE(lut) << "a texture-sampling (LUT) variant";
}

TEST(GlPlatformCli, TheLibraryDrawsBitIdenticallyOnOsMesaAndEgl) {
  const TempDir dir("gl_platform");
  const PlatformRun osmesa = run_library_on("", dir, "osmesa");
  ASSERT_EQ(osmesa.status, 0) << osmesa.output;
  ASSERT_TRUE(osmesa.results.is_object()) << osmesa.output;
  EXPECT_EQ(osmesa.results["tools"]["gl_platform"], "osmesa") << "OSMesa is the default";

  const PlatformRun egl = run_library_on("--gl-platform egl", dir, "egl");
  ASSERT_EQ(egl.status, 0) << egl.output;
  ASSERT_TRUE(egl.results.is_object()) << egl.output;
  EXPECT_EQ(egl.results["tools"]["gl_platform"], "egl surfaceless");
  EXPECT_EQ(egl.results["tools"]["mesa"]["gl"], osmesa.results["tools"]["mesa"]["gl"]) << "one driver, two ways in";
  EXPECT_EQ(egl.results["results"].size(), osmesa.results["results"].size());

  expect_every_gl_path_and_a_texture(dir / "osmesa-images");
  const size_t compared = expect_identical_images(dir / "osmesa-images", dir / "egl-images");
  EXPECT_GT(compared, 30u) << "the library's GL cells";
  std::printf("[ measured ] %zu GL cells bit-identical on OSMesa and EGL surfaceless\n", compared);
}

TEST(GlPlatformCli, AnEglDeviceChosenByNameDrawsAndIsRecorded) {
  const TempDir dir("gl_device");
  const std::string json = dir / "results.json";
  // --gl-device alone implies --gl-platform egl.
  const auto [status, out] = shaderbed_cli("run --gl-device software --case lambert --variant pixel --backend gl "
                                           "--shape sphere --size 24 --repeat 0 --quiet --json " + json);
  ASSERT_EQ(status, 0) << out;
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  const std::string platform = j["tools"]["gl_platform"];
  EXPECT_TRUE(platform.starts_with("egl device ")) << platform;
  EXPECT_NE(platform.find("software"), std::string::npos) << platform;
  for (const auto& cell : j["results"]) EXPECT_EQ(cell["status"], "pass") << cell.dump();
}

TEST(GlPlatformCli, AnUnknownPlatformIsBadInputWithTheNearestName) {
  const auto [status, out] = shaderbed_cli("run --gl-platform osmessa --case lambert --size 24 --repeat 0");
  EXPECT_EQ(status, 2) << out;
  EXPECT_TRUE(out.starts_with("shaderbed: --gl-platform: ")) << out;
  EXPECT_NE(out.find("did you mean 'osmesa'"), std::string::npos) << out;
}

TEST(GlPlatformCli, AnEglDeviceThatDoesNotExistIsBadInputListingTheDevices) {
  const auto [status, out] = shaderbed_cli("run --gl-device no-such-gpu --case lambert --size 24 --repeat 0");
  EXPECT_EQ(status, 2) << out;
  EXPECT_TRUE(out.starts_with("shaderbed: --gl-device: ")) << out;
  EXPECT_NE(out.find("matches none"), std::string::npos) << out;
  EXPECT_NE(out.find("software"), std::string::npos) << "the error lists the devices there are:\n" << out;
}

TEST(GlPlatformCli, AnEglDeviceOnOsMesaIsBadInput) {
  const auto [status, out] =
      shaderbed_cli("run --gl-platform osmesa --gl-device 0 --case lambert --size 24 --repeat 0");
  EXPECT_EQ(status, 2) << out;
  EXPECT_NE(out.find("--gl-platform egl"), std::string::npos) << out;
}

TEST(GlPlatformCli, DevicesListsTheEglDevicesAndThePlatform) {
  const auto [status, out] = shaderbed_cli("devices --gl-platform egl");
  ASSERT_EQ(status, 0) << out;
  EXPECT_NE(out.find("egl devices (--gl-device"), std::string::npos) << out;
  EXPECT_NE(out.find("software"), std::string::npos) << out;
  EXPECT_NE(out.find("on egl surfaceless"), std::string::npos) << out;
}

}  // namespace
}  // namespace shaderbed
