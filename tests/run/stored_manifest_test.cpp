// The stored-images manifest parser (run/StoredManifest.h) alone; the CLI's handling of
// a folder of stored images is tests/run/stored_images_test.cpp, and
// fuzz/stored_manifest_fuzzer.cpp runs the parser on any bytes.
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "run/StoredManifest.h"

namespace {

TEST(StoredManifest, ReadsBackWhatItWritesAndRefusesWhatItCannotTrust) {
  shaderbed::StoredManifest m;
  m.size = 32;
  m.tools.glslang = "15.1";
  m.images["c/v/glsl/vulkan/spirv/sphere"] = {.file = "c/v/sphere/glsl-vulkan-spirv.exr", .scene = "ab",
                                             .vertex_spirv_hash = "1", .fragment_spirv_hash = "2"};
  const std::string text = shaderbed::stored_manifest_text(m);
  const auto back = shaderbed::parse_stored_manifest(text, "m.json");
  ASSERT_TRUE(back) << back.error().to_string();
  EXPECT_EQ(back->size, 32);
  EXPECT_EQ(back->tools.glslang, "15.1");
  EXPECT_EQ(back->images, m.images);
  EXPECT_EQ(shaderbed::stored_manifest_text(*back), text);
  for (const auto& [bad, expected] : std::vector<std::pair<std::string, std::string>>{
           {"", "not a JSON object"},
           {"[]", "not a JSON object"},
           {R"({"images": {}})", "no image size"},
           {R"({"size": 1e3, "images": {}})", "'size' is a number"},
           {R"({"size": -4, "images": {}})", "not an image size"},
           {R"({"size": 16, "schema": 99, "images": {}})", "newer"},
           {R"({"size": 16})", "no 'images'"},
           {R"({"size": 16, "images": {"a": 1}})", "entry 'a': is a number"},
           {R"({"size": 16, "images": {"a": {}}})", "entry 'a': has no file"},
           {R"({"size": 16, "images": {"a": {"file": ""}}})", "is empty"},
           {R"({"size": 16, "images": {"a": {"file": "x/../../y.exr"}}})", "'..'"},
           {R"({"size": 16, "images": {"a": {"file": "/etc/passwd"}}})", "absolute"},
           {R"({"size": 16, "images": {"a": {"file": "x.exr", "spirv_hash": "z"}}})", "'spirv_hash' is a string"},
           {R"({"size": 16, "images": {"a": {"file": "x.exr", "spirv_hash": {"vertex": null}}}})", "'spirv_hash.vertex' is null"},
       }) {
    const auto parsed = shaderbed::parse_stored_manifest(bad, "m.json");
    ASSERT_FALSE(parsed) << bad;
    EXPECT_NE(parsed.error().to_string().find(expected), std::string::npos) << bad << ": " << parsed.error().to_string();
    EXPECT_EQ(parsed.error().file, "m.json");
  }
}

}  // namespace
