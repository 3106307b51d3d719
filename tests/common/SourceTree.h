#pragma once
// Where the tests find the project's own files: the source tree the build was made from.
#include <filesystem>

namespace shaderbed::test {

inline const std::filesystem::path kSource = SHADERBED_SOURCE_DIR;
inline const std::filesystem::path kShaders = kSource / "shaders";   // the library's shaders and cases

}  // namespace shaderbed::test
