#pragma once
// How --vulkan-device and --gl-device name a device: its index in enumeration order, or
// a case-insensitive part of its name that only one device has.
#include <string>
#include <vector>

#include "core/Error.h"

namespace shaderbed {

// The index `choice` names among `names` (in enumeration order); otherwise an error in
// `option`'s words that lists the `kind` there are ("Vulkan devices", "EGL devices").
Result<size_t> match_device(const std::vector<std::string>& names, const std::string& choice, const std::string& option,
                            const std::string& kind);

}  // namespace shaderbed
