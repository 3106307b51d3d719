#include "compile/ToolVersions.h"

#include <glslang/Public/ShaderLang.h>
#include <spirv-tools/libspirv.h>

#include "compile/StageFingerprint.gen.h"

#ifndef SHADERBED_SPIRV_CROSS_VERSION
#define SHADERBED_SPIRV_CROSS_VERSION "unknown"
#endif

namespace shaderbed {

CompilerVersions compiler_versions() {
  const glslang::Version g = glslang::GetVersion();
  return {std::to_string(g.major) + "." + std::to_string(g.minor) + "." + std::to_string(g.patch),
          spvSoftwareVersionString(),
          // SPIRV-Cross has no version API; the build records the package version.
          SHADERBED_SPIRV_CROSS_VERSION};
}

std::string compile_stage_fingerprint() { return SHADERBED_COMPILE_STAGE_FINGERPRINT; }

}  // namespace shaderbed
