#pragma once
// Output paths checked before any work is done, so an unwritable --out or --json is found
// in a millisecond instead of after the whole run has rendered.
#include <string>
#include <vector>

#include "core/Error.h"

namespace shaderbed {

// A file to be written: its folder exists (or is created) and is writable, and the path
// is not a folder. `what` names the option in the message ("--json").
Result<void> check_writable_file(const std::string& path, const std::string& what);

// A folder to be written into: it exists (or is created) and is writable.
Result<void> check_writable_folder(const std::string& path, const std::string& what);

// Whether two paths name one file: the same inode when both exist, else the same
// canonical spelling (a file yet to be written through another path to it).
bool same_file(const std::string& a, const std::string& b);

// An output must never be one of the command's inputs (`--json CASE.toml`, `init x.hlsl
// --out x.hlsl`): writing it would destroy what the user wrote. Names both in the message.
Result<void> check_not_an_input(const std::string& output, const std::string& what,
                                const std::vector<std::string>& inputs);

}  // namespace shaderbed
