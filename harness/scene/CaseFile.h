#pragma once
// A case file (shaders/cases/NAME.toml) names a lighting model, its parameters, the
// shader files per variant and language, how each shader's uniforms are bound, and the
// tolerances with their reasons. A case declares only what its shaders use.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "pipeline/SamplerSettings.h"
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
  // A DX9 effect (.fx, compile/EffectFrontEnd.h): the technique and pass whose
  // `compile` statements give the entries and whose states the draw uses; "" = the first.
  std::string technique;
  std::string pass;
  // Preprocessor defines (`defines`: the case's, its language's, then the variant's own,
  // a later one replacing an earlier of the same name) and include folders (absolute,
  // `include_dirs`, searched after the including file's folder).
  std::vector<std::pair<std::string, std::string>> defines;
  std::vector<std::string> include_dirs;
};

enum class LightingMode { per_vertex, per_pixel };

struct Variant {
  std::string name;                         // "vertex", "pixel", ...
  LightingMode mode = LightingMode::per_pixel;
  std::map<Language, ShaderFiles> shaders;  // languages this variant is written in
  std::string lut;                          // generated lookup texture ("" = none), bound as "lut"
};

// A channel passes when |render - reference| <= max_abs + max_rel * |reference|.
struct Tolerance {
  double max_abs = 0;
  std::string reason;
  double max_rel = 0;
};

// One part of a binding: a scene quantity or case parameter by name, or literal numbers
// (`padding = 0.0`, `ambientColor = [0.1, 0.1, 0.1]`, `useFog = false`).
struct BindingSource {
  std::string name;              // "" for a literal
  std::vector<double> literal;
};

// How a matrix binding is uploaded. column_vector: M of "clip = M v", for mul(M, v) and
// GLSL's M * v. row_vector: its transpose, so an effect that writes mul(v, M) with D3DX
// matrices runs unchanged (`{ value = "transform", layout = "row_vector" }`).
enum class MatrixLayout { column_vector, row_vector };

// Uniform name (or HLSL register "cN") -> the sources whose values, concatenated, fill it
// (e.g. SpecularColor = ["specular", "power"]).
struct Binding {
  std::vector<BindingSource> sources;
  MatrixLayout layout = MatrixLayout::column_vector;
  int line = 0;                  // where the case file binds it
  bool literal() const;          // every source is a literal
  // The name when the binding is exactly one name (a sampler binds one texture), else "".
  std::string single_name() const;
};
using BindingTable = std::map<std::string, Binding>;

// The light a case's models use (`light = "directional" | "point"`); model_default keeps
// each model's own (docs/models.md).
enum class CaseLight { model_default, directional, point };

// A `[textures]` entry: an image file for a sampler or texture (by the name the shader
// declares: the sampler2D, or the Texture2D of an SM4 pair), or settings only for a
// SamplerState. What the entry names overrides the effect's sampler_state and, for a
// texture, its sampler state's entry (backends/SamplerSettings.h says the order).
enum class MipSource { none, generate, file };   // `mipmaps = false | true | "file"`
struct TextureBinding {
  std::vector<std::string> files;   // absolute; none: settings only; six: a cube map (+X, -X, +Y, -Y, +Z, -Z)
  std::optional<MipSource> mipmaps;
  SamplerSettingsPatch settings;    // filter, address, border, color = "srgb" | "linear"
  int line = 0;                     // where the case file binds it
  int column = 0;
};
// `[textures]` holds the entries every language uses; `[textures.<language>]` adds or
// replaces entries for one language, whose shaders may name their textures differently.
struct TextureTable {
  std::map<std::string, TextureBinding> common;
  std::map<Language, std::map<std::string, TextureBinding>> per_language;
  // The entries a cell of `language` uses.
  std::map<std::string, TextureBinding> for_language(Language language) const;
};

// A differential case's reference: the original shader drawn by one backend and path
// (`reference = { language = "hlsl", backend = "vulkan", path = "spirv" }`), or the
// images a known-good run stored (`reference = { images = "DIR" }`, run --save-images).
struct RenderReference {
  Language language = Language::hlsl;
  // "vulkan" | "gl" | "twin-double" | "twin-float" | "twin-half" (twin = ...; the default
  // when the case names no backend or path)
  std::string backend = "vulkan";
  std::string path = "spirv";       // "spirv" | "glsl" | "cross" (backends/Backend.h to_string(ShaderPath))
  std::string variant;              // whose shaders are the original; "" = each variant its own
  int line = 0;
};

// `[sh]`: the spherical-harmonic cases' choices that are not numbers (harness/prt,
// docs/sh.md); their numbers (bands, grid, clusters, ...) are parameters, so --param and
// sweep reach them.
struct ShSetup {
  std::string transfer = "shadowed";   // unshadowed | shadowed | interreflected
  std::string light = "directional";   // directional | cone | sky | probe
  std::string probe;                   // light = "probe": an .hdr or .exr file (absolute)
  std::string mapping = "latlong";     // the probe's mapping: latlong | angular
  bool ground = false;                 // a ground plane under the shape shadows and bounces
  int line = 0;
};

struct Case {
  std::string name;          // file stem
  std::string path;
  std::string model;         // reference model name; "" in a differential case (reference_render or reference_images)
  std::optional<RenderReference> reference_render;
  std::string reference_images;   // absolute folder of stored images, "" = none
  int model_line = 0;        // where the case names it
  std::string description;
  std::map<std::string, std::vector<double>> params;
  std::vector<Variant> variants;
  std::map<Language, BindingTable> bindings;
  std::map<Language, AttributeTable> attributes;   // [attributes.<language>] (scene/Mesh.h)
  CaseLight light = CaseLight::model_default;
  std::optional<glm::dvec3> ambient;   // `ambient = [r, g, b]`: added to every model's output
  TextureTable textures;     // [textures]: image files and sampler settings by sampler name
  // A model case without [tolerance]: run/ gives it the library case's for its model
  // (complete_case), derived for the model's whole parameter range.
  bool tolerance_from_model = false;
  Tolerance interior;        // pixels whose 3x3 neighbourhood is covered in the reference
  Tolerance silhouette;      // the one-pixel band around the reference's silhouette
  // LUT variants are compared with the analytic reference; max_abs < 0 means "derive
  // it from the LUT size" (see lut/), the reason says how.
  std::optional<Tolerance> lut;
  // SH cases: the bound on the approximation's own error (truncated SH against the exact
  // integral), so a wrong projection fails even when the shader matches it.
  std::optional<Tolerance> approximation;
  std::optional<ShSetup> sh;
  Tessellation tessellation = Tessellation::low;

  // Judged against a render (of the original, or stored) instead of a model.
  bool differential() const { return model.empty(); }
};

// The tolerances a differential case gets when it states none (documented in CaseFile.cpp).
Tolerance differential_interior_tolerance();
Tolerance differential_silhouette_tolerance();

// Where a case's shader, texture and include paths are relative to: the folder that holds
// a `cases/` folder (the library's shaders/cases, tests/realworld/cases), else the case
// file's own folder (a user's case written next to their shader).
std::filesystem::path shader_root_of(const std::string& case_path);

Result<Case> load_case(const std::string& path);

// The case files (*.toml) in a directory, sorted by name.
Result<std::vector<std::string>> list_case_files(const std::string& directory);

// Every case in a directory; the first broken file is the error.
Result<std::vector<Case>> load_cases(const std::string& directory);

Result<Language> parse_language(const std::string&);

}  // namespace shaderbed
