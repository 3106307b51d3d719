#pragma once
// Writes a whole file so that a reader (or a run killed mid-write) sees either the old
// file or the new one, never a truncated mix: the bytes go to a temporary file in the same
// folder, flushed, then renamed over the target.
#include <string>
#include <string_view>

#include "core/Error.h"

namespace shaderbed {

// Creates the file's folder if needed. `what` names the file in errors ("JSON report").
Result<void> write_file_atomically(const std::string& path, std::string_view bytes, const std::string& what);

}  // namespace shaderbed
