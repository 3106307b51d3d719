#pragma once
// `shaderbed port`: a case's original shaders ported by SPIRV-Cross (compile/PortSource.h)
// and the differential case that judges the port against the original's render. The case
// keeps the original's parameters, light, textures and bindings, and binds the port's
// uniforms to the same quantities under the port's names: register bindings ("c4") and
// legacy GLSL built-ins become names, a matrix whose register convention differs in the
// port gets the other `layout`, vertex inputs whose semantics are lost are placed under
// [attributes.glsl]. Nothing is written until write_port.
#include <string>
#include <vector>

#include "compile/PortSource.h"
#include "core/Error.h"

namespace shaderbed {

struct PortOptions {
  std::string case_path;    // the original's case file (.toml)
  std::string from;         // the original's language; "" = the case's reference language, else its only one
  PortTarget target = PortTarget::glsl;
  std::string out_dir;      // "" = <case folder>/<case stem>.port.<target>
};

struct PortFile {
  std::string path;         // absolute
  std::string text;
};

struct PortPlan {
  std::string out_dir;
  std::vector<PortFile> files;             // the ported shaders, then the case files
  std::vector<std::string> case_paths;     // the case files among them, to run
  std::vector<PortChange> changes;         // each once, prefixed with the variants it applies to
};

// Ports every variant that has the original's language; bad input (a shader instead of a
// case, an unknown or ambiguous --from, a port that does not compile back) is an Error.
Result<PortPlan> plan_port(const PortOptions& options);

// The planned files that already exist (the command refuses them without --force).
std::vector<std::string> existing_port_files(const PortPlan& plan);

// Writes every file, creating the folder; each file whole (a temporary renamed over it).
Result<void> write_port(const PortPlan& plan);

}  // namespace shaderbed
