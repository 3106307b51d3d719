#pragma once
// Errors are values: every stage returns Result<T>, and the CLI turns an Error into one
// readable line. Fields that do not apply stay empty/zero and are left out of the text.
#include <expected>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace shaderbed {

// Where an error arose: a stage of the pipeline, a command or an input. Its name is
// printed in the error's text (to_string), nowhere compared as a string.
enum class ErrorStage {
  none,
  against,          // --against
  backend,
  bench,
  bind,
  case_file,        // "case"
  compile,
  counterfactual,
  cross_compile,
  display,
  draw,
  expectations,
  gl,
  image,
  init,
  isolation,
  lut,
  merge,
  nir,
  optimize,
  options,
  plot,
  port,
  reference,
  reflect,
  report,
  screenshot,
  sh,
  stats,
  stored_images,
  sweep,
  texture,
  validate,
  viewer,
  twin,             // the shader's twin (twin/)
  vulkan,
  worker,
};
const char* to_string(ErrorStage);
std::optional<ErrorStage> parse_error_stage(std::string_view text);

struct Error {
  std::string message;
  std::string file;     // source file the error refers to (shader, case file), if any
  int line = 0;         // 1-based; 0 = unknown
  int column = 0;       // 1-based; 0 = unknown
  ErrorStage stage = ErrorStage::none;
  std::string backend;  // backend/path the error happened on, if any
  // Not a fault: the cell's path does not apply to this shader (Vulkan-only GLSL on the
  // native GL path, say). The runner reports it as status "skipped" with the message.
  bool skipped = false;

  // "file:line:col: stage[backend]: message"
  std::string to_string() const;

  // Prefix context without losing what is already there.
  Error&& in_stage(ErrorStage s) && {
    if (stage == ErrorStage::none) stage = s;
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

inline std::unexpected<Error> fail(ErrorStage stage, std::string message) {
  return std::unexpected(Error{.message = std::move(message), .stage = stage});
}

// A path that does not apply, with the reason (status "skipped", never an error).
inline std::unexpected<Error> skip(ErrorStage stage, std::string reason) {
  return std::unexpected(Error{.message = std::move(reason), .stage = stage, .skipped = true});
}

}  // namespace shaderbed
