#pragma once
// Reads a text file a user names (a shader, an #include, a case file) without trusting
// it: only a regular file, and only up to a size no real one reaches, so `/dev/zero` or a
// FIFO is one error instead of a read until memory runs out or a wait forever.
#include <cstddef>
#include <string>

#include "core/Error.h"

namespace shaderbed {

constexpr size_t kMaxSourceBytes = size_t(16) << 20;   // 16 MiB: the largest library shader is ~10 KiB

// The file's bytes; an Error (stage `stage`, naming the file) for a missing or unreadable
// file, a non-regular file, or one larger than `limit`. `what` names it in the message
// ("shader file", "#include").
Result<std::string> read_bounded_file(const std::string& path, const std::string& what, ErrorStage stage,
                                      size_t limit = kMaxSourceBytes);

// read_bounded_file's checks alone, for a file another library opens (an image through
// OpenImageIO): it exists, is a regular file, and has at most `limit` bytes.
Result<void> check_bounded_file(const std::string& path, const std::string& what, ErrorStage stage, size_t limit);

}  // namespace shaderbed
