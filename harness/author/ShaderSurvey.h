#pragma once
// What `shaderbed init` learns about the shaders it is given before it writes a case:
// the files grouped by language (by extension, or all in the language --lang names), each
// language's vertex and fragment file and entry points (a DX9 effect's first technique
// and pass; HLSL/Cg functions whose outputs carry POSITION / COLOR; GLSL main() in its
// .vert/.frag file), and, from a compile with the same front ends the runner uses (so
// the names are the ones it binds), every uniform with what its declaration says, the
// vertex inputs and the samplers.
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "author/BindingGuess.h"
#include "compile/ShaderModule.h"
#include "pipeline/SamplerSettings.h"
#include "core/Error.h"
#include "scene/CaseFile.h"

namespace shaderbed {

struct SurveyedLanguage {
  Language language = Language::hlsl;
  ShaderFiles files;                   // absolute paths; entries, technique and pass as found
  std::vector<std::string> notes;      // how the entries were found, for the case's comments
  std::string compile_error;           // "" = compiled; else what the compile said (the case is still written)
  std::vector<UniformFacts> uniforms;  // both stages, each name once, in declaration order
  std::vector<StageInput> inputs;      // the vertex stage's
  std::vector<SamplerBinding> samplers;   // both stages, each name once
  // A DX9 effect's `sampler_state { ... }` settings by sampler name: the runner samples
  // with these, so a port must be given the same.
  std::vector<std::pair<std::string, SamplerSettings>> declared_sampling;
};

// The language of a shader file: its extension's, else (.vs, or an extension that says
// nothing) its text's: GLSL when it has #version or writes gl_ built-ins, a Unity
// ShaderLab file's program block's (CGPROGRAM: cg, HLSLPROGRAM: hlsl); an error naming
// the file when neither says.
Result<Language> language_of_file(const std::string& path, std::string_view text);

// What the case gives every front end's preprocessor (`defines`, `include_dirs`; init's
// --define and --include-dir): the survey compiles with them and the case keeps them.
struct SurveyPreprocessor {
  std::vector<std::pair<std::string, std::string>> defines;
  std::vector<std::string> include_dirs;   // absolute
};

// `paths` as given on the command line; `forced` = --lang. Bad input (a missing file, an
// unknown extension, no entry point, a GLSL language without a vertex or fragment file)
// is an error naming the file.
Result<std::vector<SurveyedLanguage>> survey_shaders(const std::vector<std::string>& paths,
                                                     std::optional<Language> forced,
                                                     const SurveyPreprocessor& preprocessor = {});

}  // namespace shaderbed
