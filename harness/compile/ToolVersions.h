#pragma once
#include <string>

namespace shaderbed {

struct CompilerVersions {
  std::string glslang, spirv_tools, spirv_cross;
};

// Versions of the compilers linked into this build, recorded in every result.
CompilerVersions compiler_versions();

}  // namespace shaderbed
