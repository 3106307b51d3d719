// The textured differential corpus (tests/differential: a toon ramp, a normal map, an sRGB
// albedo): correct ports pass at every image size and on every path within the derived
// 8-bit texel bound (run/TexelStepBound.h), and the texture mutants still fail.
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "FileContents.h"
#include "ShellCommand.h"
#include "TempDir.h"

namespace {

using shaderbed::test::read_json;
using shaderbed::test::shaderbed_cli;
namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kCases = fs::path(SHADERBED_SOURCE_DIR) / "tests" / "differential" / "cases";

std::string corpus_cases(std::initializer_list<const char*> names) {
  std::string list;
  for (const char* n : names) list += (list.empty() ? "" : ",") + (kCases / (std::string(n) + ".toml")).string();
  return list;
}

class TexturedPortsAtSize : public testing::TestWithParam<int> {};

// 32 and 67 (odd, so pixel centres fall elsewhere on the texels) up to 512: the one-pixel
// failures were size-dependent.
TEST_P(TexturedPortsAtSize, PassOnEveryPathWithinTheDerivedTexelBound) {
  const int size = GetParam();
  shaderbed::test::TempDir dir("textured_ports");
  const std::string results = dir / "results.json";
  const auto [status, out] = shaderbed_cli("run --case " + corpus_cases({"toon_ramp", "normal_map", "srgb_albedo"}) +
                                           " --variant original,port --size " + std::to_string(size) +
                                           " --repeat 0 -q --json " + results);
  EXPECT_EQ(status, 0) << out;
  const json j = read_json(results);
  std::map<std::string, int> cells;   // case/language/backend/path -> shapes
  for (const json& r : j["results"]) {
    EXPECT_EQ(r["status"], "pass") << r["id"] << ": " << r["message"] << " " << r["attribution"];
    EXPECT_NE(r["attribution"]["verdict"], "port") << r["id"];
    // The bound is derived for each group, with its reason, and stays within a few steps.
    const double texels = r["tolerance"]["texels"]["bound"].get<double>();
    EXPECT_GT(texels, 1.0 / 255) << r["id"];
    EXPECT_LT(texels, 8.0 / 255) << r["id"];
    EXPECT_NE(r["tolerance"]["texels"]["derivation"].get<std::string>().find("8-bit"), std::string::npos);
    ++cells[r["case"].get<std::string>() + "/" + r["language"].get<std::string>() + "/" + r["backend"].get<std::string>() +
            "/" + r["path"].get<std::string>()];
  }
  // Each case: the original's language on its paths and the port's, every one on four shapes.
  EXPECT_EQ(cells.size(), 3u * 7u);
  for (const auto& [path, shapes] : cells) EXPECT_EQ(shapes, 4) << path;
}

INSTANTIATE_TEST_SUITE_P(Sizes, TexturedPortsAtSize, testing::Values(32, 67, 128, 256, 512));

// Flipped v, swapped channels and sRGB decoded as linear each move pixels by many steps:
// the texel bound must not absorb them, at the smallest size and the largest.
TEST(TexturedPorts, TextureMutantsStillFail) {
  shaderbed::test::TempDir dir("textured_mutants");
  for (const int size : {32, 512}) {
    const std::string results = dir / ("mutants" + std::to_string(size) + ".json");
    const auto [status, out] =
        shaderbed_cli("run --case " + corpus_cases({"toon_ramp", "normal_map", "srgb_albedo_as_linear"}) +
                      " --variant swapped_channels,flipped_v,port --shape sphere,torus --size " + std::to_string(size) +
                      " --repeat 0 -q --json " + results);
    EXPECT_EQ(status, 1) << out;
    const json j = read_json(results);
    std::map<std::string, int> failing;
    for (const json& r : j["results"]) {
      const std::string which = r["case"].get<std::string>() + "/" + r["variant"].get<std::string>();
      // The correct ports the variant filter also selects (toon_ramp's, normal_map's) are not mutants.
      if (which == "toon_ramp/port" || which == "normal_map/port") continue;
      EXPECT_EQ(r["status"], "fail") << r["id"] << " at " << size;
      ++failing[which];
    }
    // Every path the mutant's language runs on, on both shapes.
    EXPECT_EQ(failing["toon_ramp/swapped_channels"], 8) << out;
    EXPECT_EQ(failing["normal_map/flipped_v"], 6) << out;
    EXPECT_EQ(failing["srgb_albedo_as_linear/port"], 8) << out;
  }
}

// A case whose original is judged on GL (normal_map.toml: glsl on gl/glsl) still draws it
// there when the run is filtered to Vulkan (a filter chooses the cells judged, not their reference); on gl/spirv too.
TEST(TexturedPorts, AGlJudgedOriginalIsDrawnUnderAVulkanFilter) {
  shaderbed::test::TempDir dir("gl_original");
  // Shader and texture paths are relative to the folder above cases/.
  fs::create_directories(dir / "cases");
  for (const char* folder : {"glsl", "hlsl", "textures"})
    fs::copy(kCases.parent_path() / folder, dir / folder, fs::copy_options::recursive);
  for (const char* path : {"glsl", "spirv"}) {
    const fs::path copy = dir / (std::string("normal_map_") + path + ".toml");
    std::string text = shaderbed::test::read_text(kCases / "normal_map.toml");
    const std::string from = "path = \"glsl\"";
    text.replace(text.find(from), from.size(), std::string("path = \"") + path + "\"");
    const fs::path the_case = fs::path(dir / "cases") / copy.filename();
    { std::ofstream(the_case) << text; }
    const std::string results = dir / (std::string(path) + ".json");
    const auto [status, out] = shaderbed_cli("run --case " + the_case.string() +
                                             " --variant original,port --backend vulkan --shape sphere --size 48 "
                                             "--repeat 0 -q --json " + results);
    EXPECT_EQ(status, 0) << out;
    const json j = read_json(results);
    ASSERT_EQ(j["results"].size(), 2u) << out;   // glsl and hlsl on vulkan/spirv
    for (const json& r : j["results"]) {
      EXPECT_EQ(r["status"], "pass") << r["id"] << ": " << r["message"];
      EXPECT_EQ(r["backend"], "vulkan");
      EXPECT_EQ(r["reference"]["label"], std::string("glsl gl/") + path + " (variant original)");
    }
  }
}

}  // namespace
