// `shaderbed --version`: the version and the toolchain fingerprint every result records.
// The drivers are started to ask them theirs, so this is the one flag that loads them.
#include <fmt/format.h>

#include "cli/commands/Command.h"
#include "run/CellPlan.h"
#include "run/Toolchain.h"

namespace shaderbed {

void add_version_flag(CLI::App& app) {
  app.set_version_flag("--version", [] {
    const std::vector<BackendSlot> backends = start_backends({});
    std::string text = version_text(toolchain(backends));
    if (!text.empty() && text.back() == '\n') text.pop_back();   // CLI11 adds the newline
    return text;
  }, "Print shaderbed's version and the toolchain fingerprint (glslang, SPIRV-Tools, SPIRV-Cross, Mesa, LLVM, device) and exit");
}

}  // namespace shaderbed
