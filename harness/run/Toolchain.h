#pragma once
// The toolchain fingerprint every result records and `shaderbed --version` prints: the
// compilers linked in, and the drivers and device the started backends run on.
#include <string>
#include <vector>

#include "report/Results.h"
#include "run/CellPlan.h"

namespace shaderbed {

ToolVersions toolchain(const std::vector<BackendSlot>& backends);

// "shaderbed 0.5.0", then a line per tool.
std::string version_text(const ToolVersions& tools);

}  // namespace shaderbed
