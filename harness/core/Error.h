#pragma once
// Errors are values: every stage returns Result<T>, and the CLI turns an Error into one
// readable line. Fields that do not apply stay empty/zero and are left out of the text.
#include <expected>
#include <string>
#include <utility>

namespace shaderbed {

struct Error {
  std::string message;
  std::string file;     // source file the error refers to (shader, case file), if any
  int line = 0;         // 1-based; 0 = unknown
  int column = 0;       // 1-based; 0 = unknown
  std::string stage;    // "compile", "vulkan", "gl", "case", "reference", ...
  std::string backend;  // backend/path the error happened on, if any
  // Not a fault: the cell's path does not apply to this shader (Vulkan-only GLSL on the
  // native GL path, say). The runner reports it as status "skipped" with the message.
  bool skipped = false;

  // "file:line:col: stage[backend]: message"
  std::string to_string() const;

  // Prefix context without losing what is already there.
  Error&& in_stage(std::string s) && {
    if (stage.empty()) stage = std::move(s);
    return std::move(*this);
  }
  Error&& in_backend(std::string b) && {
    if (backend.empty()) backend = std::move(b);
    return std::move(*this);
  }
  Error&& in_file(std::string f) && {
    if (file.empty()) file = std::move(f);
    return std::move(*this);
  }
};

template <class T>
using Result = std::expected<T, Error>;

inline std::unexpected<Error> fail(std::string stage, std::string message) {
  return std::unexpected(Error{.message = std::move(message), .stage = std::move(stage)});
}

// A path that does not apply, with the reason (status "skipped", never an error).
inline std::unexpected<Error> skip(std::string stage, std::string reason) {
  return std::unexpected(Error{.message = std::move(reason), .stage = std::move(stage), .skipped = true});
}

}  // namespace shaderbed
