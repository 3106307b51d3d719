// A texture that is a FIFO, /dev/zero or a decompression bomb is an error cell of stage
// "texture" naming the texture and its file, found before anything is decoded; not a
// compile timeout after 30 s or a "compiler crashed: SIGABRT" (issue 30, item 13).
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ShellCommand.h"
#include "SourceTree.h"
#include "TempDir.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

// tests/viewer/one_draw (a DX9 effect sampling fx/tan_constant.png) in `root`, its texture
// made by `make_texture`; runs its one Vulkan cell and returns the cell.
template <class MakeTexture>
nlohmann::json run_with_texture(const test::TempDir& root, MakeTexture make_texture) {
  fs::copy(fs::path(SHADERBED_SOURCE_DIR) / "tests" / "viewer" / "one_draw", root.path() / "tree",
           fs::copy_options::recursive);
  const fs::path texture = root.path() / "tree" / "fx" / "tan_constant.png";
  fs::remove(texture);
  make_texture(texture.string());
  const std::string json = root / "r.json";
  const auto [status, out] = test::run_shell(
      "timeout 120 " + std::string(SHADERBED_BINARY) + " run --cases-dir " + (root.path() / "tree" / "cases").string() +
      " --case textured_lambert --backend vulkan --shape sphere --size 16 --repeat 0 --quiet --json " + json);
  std::ifstream in(json);
  if (!in) {
    ADD_FAILURE() << "no JSON; exit " << status << ": " << out;
    return {};
  }
  const nlohmann::json report = nlohmann::json::parse(in);
  if (report["results"].size() != 1) {
    ADD_FAILURE() << report.dump();
    return {};
  }
  return report["results"][0];
}

// The texture's own error (stage "texture"), not the compile watchdog's timeout that
// caught these before.
void expect_texture_error(const nlohmann::json& cell, const std::string& says) {
  ASSERT_FALSE(cell.is_null());
  EXPECT_EQ(cell["status"], "error") << cell.dump();
  EXPECT_EQ(cell.value("error_stage", ""), "texture") << cell.dump();
  const std::string message = cell["message"];
  EXPECT_NE(message.find("texture 'AlbedoSampler'"), std::string::npos) << message;
  EXPECT_NE(message.find("tan_constant.png"), std::string::npos) << message;
  EXPECT_NE(message.find(says), std::string::npos) << message;
  EXPECT_EQ(message.find("longer than"), std::string::npos) << message;
}

TEST(TextureBounds, AFifoIsRefusedNotWaitedOn) {
  test::TempDir root("texture_fifo");
  const nlohmann::json cell =
      run_with_texture(root, [](const std::string& p) { ASSERT_EQ(::mkfifo(p.c_str(), 0644), 0); });
  expect_texture_error(cell, "not a regular file");
}

TEST(TextureBounds, DevZeroIsRefusedNotRead) {
  test::TempDir root("texture_zero");
  const nlohmann::json cell = run_with_texture(
      root, [](const std::string& p) { fs::create_symlink("/dev/zero", p); });
  expect_texture_error(cell, "not a regular file");
}

TEST(TextureBounds, APngDeclaring30000SquaredIsRefusedFromItsHeader) {
  test::TempDir root("texture_bomb");
  const nlohmann::json cell = run_with_texture(
      root,
      [](const std::string& p) {
        const std::string script =
            (fs::path(SHADERBED_SOURCE_DIR) / "tests" / "run" / "texture_files" / "png_bomb.py").string();
        const auto [status, out] = test::run_shell("python3 " + script + " " + p);
        ASSERT_EQ(status, 0) << out;
        ASSERT_LT(fs::file_size(p), size_t(2) << 20) << "a small file";
      });
  expect_texture_error(cell, "declares 30000x30000");
}

// OpenEXR 3.1 would allocate the 1.8 GB the Software attribute declares before finding
// that the 60-byte file does not hold it (texture_loader_fuzzer's find).
TEST(TextureBounds, AnExrDeclaringAnAttributeLargerThanItselfIsRefusedFromItsHeader) {
  test::TempDir root("texture_exr_attribute");
  const nlohmann::json cell = run_with_texture(root, [](const std::string& p) {
    std::ofstream out(p, std::ios::binary);
    const unsigned char start[] = {0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0};
    out.write(reinterpret_cast<const char*>(start), sizeof start);
    out.write("Software\0string\0", 16);
    const unsigned char declared[] = {0xa0, 0x00, 0x61, 0x6c};   // 0x6c6100a0 = 1818296480
    out.write(reinterpret_cast<const char*>(declared), sizeof declared);
    out << std::string(32, 'x');
  });
  expect_texture_error(cell, "attribute 'Software' (string) declares 1818296480 bytes, more than the 60-byte file holds");
}

}  // namespace
}  // namespace shaderbed
