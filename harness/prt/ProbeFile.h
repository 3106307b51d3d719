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

}  // namespace shaderbed
