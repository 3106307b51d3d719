#pragma once
// Where an installed shaderbed keeps what it reads at run time, found from the executable's
// own place, so `cmake --install build --prefix P` gives a tree that works from any directory
// and wherever it was put: P/bin/shaderbed reads P/share/shaderbed and dlopens from
// P/lib/shaderbed. In the build tree neither folder exists and both are empty.
#include <filesystem>

namespace shaderbed {

// P/share/shaderbed (which holds shaders/, with the library's cases), or empty.
std::filesystem::path installed_data_dir();

// P/lib/shaderbed (the image-IO module), or empty.
std::filesystem::path installed_module_dir();

}  // namespace shaderbed
