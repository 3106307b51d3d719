#pragma once
// The running program's own file (/proc/self/exe), for what lives next to it (the NIR
// helper, the image module) and for starting it again as a child (bench, isolated runs).
#include <filesystem>

namespace shaderbed {

// Empty when the link cannot be read.
std::filesystem::path this_executable();

}  // namespace shaderbed
