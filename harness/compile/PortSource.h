#pragma once
// A compiled program ported to another shading language by SPIRV-Cross, written to be read:
// the original's uniform, vertex-input, varying and output names are kept (HLSL's
// "InVertex.Position" becomes "Position", varyings take the vertex output's name in both
// stages), uniform blocks keep their member names as plain identifiers, and every change
// the translation makes (combined or split samplers, lost semantics, dropped precision,
// flattened blocks, renamed identifiers) is listed, so a user can judge the port.
//
// Targets: GLSL 450 (`glsl`: named uniform blocks without an instance name, so members
// read as plain names), GLSL 330 core (`glsl-gl`: plain uniforms), HLSL SM5 (`hlsl`:
// cbuffers, vertex inputs given the semantics shaderbed places, entry points `main`).
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed {

enum class PortTarget { glsl, glsl_gl, hlsl };

Result<PortTarget> parse_port_target(std::string_view name);   // "glsl" | "glsl-gl" | "hlsl"
const char* to_string(PortTarget target);
Language language_of(PortTarget target);
// The port's file names: ".vert"/".frag" for GLSL, ".vs.hlsl"/".ps.hlsl" for HLSL.
std::string port_file_suffix(PortTarget target, Stage stage);

// One thing the translation changed or could not keep, for the user to read.
struct PortChange {
  std::string kind;      // "renamed", "semantics", "samplers", "flattened", "matrix", "precision", "entry point", ...
  std::string message;
  bool operator==(const PortChange&) const = default;
};

struct PortedStage {
  std::string text;
  std::string entry_point = "main";
  // The original's names, as its reflection and case know them -> the port's names.
  std::map<std::string, std::string> uniform_names;   // uniform block members and loose uniforms
  std::map<std::string, std::string> sampler_names;   // samplers and textures (an SM4 texture -> its combined sampler)
  // Port sampler -> the original SamplerState folded into it (HLSL pair -> GLSL sampler2D).
  std::map<std::string, std::string> folded_sampler_states;
  std::map<uint32_t, std::string> input_names;        // vertex stage: port input name by location
};

struct PortedProgram {
  PortedStage vertex;
  PortedStage fragment;
  std::vector<PortChange> changes;
};

struct PortRequest {
  PortTarget target = PortTarget::glsl;
  // HLSL target: the semantic each vertex input location gets (POSITION, NORMAL,
  // TEXCOORD0, ...), from how shaderbed places the original's inputs. Others: TEXCOORDn.
  std::map<uint32_t, std::string> input_semantics;
};

// Ports the Vulkan-target modules of `original` (compile_program; the GL ones may be empty).
Result<PortedProgram> port_program(const CompiledProgram& original, const PortRequest& request);

}  // namespace shaderbed
