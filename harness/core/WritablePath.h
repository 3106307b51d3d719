#pragma once
// Output paths checked before any work is done, so an unwritable --out or --json is found
// in a millisecond instead of after the whole run has rendered.
#include <string>

#include "core/Error.h"

namespace shaderbed {

// A file to be written: its folder exists (or is created) and is writable, and the path
// is not a folder. `what` names the option in the message ("--json").
Result<void> check_writable_file(const std::string& path, const std::string& what);

// A folder to be written into: it exists (or is created) and is writable.
Result<void> check_writable_folder(const std::string& path, const std::string& what);

}  // namespace shaderbed
