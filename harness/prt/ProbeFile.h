#pragma once
// An environment map (light probe) file as an SH light, read through the CLI's lazily
// loaded image module (imageio/ImageIoModule.h), so no command pays OpenImageIO's start-up
// unless it reads a probe.
#include <string>

#include "core/Error.h"
#include "sh/EnvironmentMap.h"

namespace shaderbed {

// Errors name the file: missing, unreadable, not a flat 2D image, an angular map not square.
Result<sh::EnvironmentMap> read_probe(const std::string& path, sh::MapLayout layout);

// `message` as a user reads it: led by `path` as they gave it, unless it names it already
// (an SH case's light reads the probe by its absolute path).
std::string naming_file(const std::string& path, const std::string& message);

}  // namespace shaderbed
