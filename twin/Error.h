#pragma once
// What the twin reports when it cannot run a shader: the reason, and where in the shader's
// source it stopped (from OpLine) when the module carries lines.
#include <expected>
#include <string>

namespace twin {

struct TwinError {
  std::string message;
  std::string file;     // source file of the instruction, "" when the module has no OpLine
  int line = 0;
  std::string to_string() const {
    return file.empty() ? message : file + ":" + std::to_string(line) + ": " + message;
  }
};

template <typename T>
using TwinResult = std::expected<T, TwinError>;

}  // namespace twin
