#pragma once
// A case file (shaders/cases/NAME.toml) names a lighting model, its parameters, the
// shader files per variant and language, how each shader's uniforms are bound, and the
// tolerances with their reasons. A case declares only what its shaders use.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "compile/ShaderModule.h"
#include "core/Error.h"
#include "scene/Primitives.h"

namespace shaderbed {

struct ShaderFiles {
  std::string vertex;     // absolute paths; existence is checked when a cell needs them,
  std::string fragment;   // so a missing file of one language does not block the others
  int line = 0;           // where the case file names them
  // The stages' entry functions (`vertex_entry`, `fragment_entry` in the case): HLSL and
  // Cg files name their own, and one file may hold both stages. GLSL is always main().
  std::string vertex_entry = "main";
  std::string fragment_entry = "main";
};

enum class LightingMode { per_vertex, per_pixel };

struct Variant {
  std::string name;                         // "vertex", "pixel", ...
  LightingMode mode = LightingMode::per_pixel;
  std::map<Language, ShaderFiles> shaders;  // languages this variant is written in
  std::string lut;                          // generated lookup texture ("" = none), bound as "lut"
};

struct Tolerance {
  double max_abs = 0;
  std::string reason;
};

// Uniform name (or HLSL register "cN") -> the scene quantities and parameters whose
// values, concatenated, fill it (e.g. SpecularColor = ["specular", "power"]).
using BindingTable = std::map<std::string, std::vector<std::string>>;

struct Case {
  std::string name;          // file stem
  std::string path;
  std::string model;         // reference model name
  std::string description;
  std::map<std::string, std::vector<double>> params;
  std::vector<Variant> variants;
  std::map<Language, BindingTable> bindings;
  Tolerance interior;        // pixels whose 3x3 neighbourhood is covered in the reference
  Tolerance silhouette;      // the one-pixel band around the reference's silhouette
  // LUT variants are compared with the analytic reference; max_abs < 0 means "derive
  // it from the LUT size" (see lut/), the reason says how.
  std::optional<Tolerance> lut;
  Tessellation tessellation = Tessellation::low;
};

Result<Case> load_case(const std::string& path);

// The case files (*.toml) in a directory, sorted by name.
Result<std::vector<std::string>> list_case_files(const std::string& directory);

// Every case in a directory; the first broken file is the error.
Result<std::vector<Case>> load_cases(const std::string& directory);

Result<Language> parse_language(const std::string&);

}  // namespace shaderbed
