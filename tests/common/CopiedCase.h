#pragma once
// A real-world case and its shaders copied into a test's folder, in the layout the case
// expects (cases/blinn.toml beside glsl330/): tests that write, move or name files around a
// case never touch the source tree.
#include <filesystem>

namespace shaderbed::test {

inline std::filesystem::path copy_blinn_phong_case(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  const fs::path from = fs::path(SHADERBED_SOURCE_DIR) / "tests/realworld";
  fs::create_directories(dir / "cases");
  fs::copy(from / "glsl330", dir / "glsl330", fs::copy_options::recursive);
  fs::copy_file(from / "cases/glsl330_blinn_phong.toml", dir / "cases/blinn.toml");
  return dir / "cases/blinn.toml";
}

}  // namespace shaderbed::test
