#pragma once
// The case file `shaderbed init` writes: a differential case (no model: the first
// language's Vulkan SPIR-V render is the reference), one `pixel` variant holding each
// language's files and entries, every uniform bound with a guess (author/BindingGuess.h)
// and a comment saying why, GLSL vertex inputs mapped by name, textures bound to the image
// next to the shader when one is the obvious choice. What it cannot guess is a TODO
// written so the file still loads: a commented-out binding with a placeholder, and a
// line in `todos` naming the case file's line.
#include <map>
#include <string>
#include <vector>

#include "author/ShaderSurvey.h"

namespace shaderbed {

// Guesses the shaders' text did not settle (author/BindingGuess.h UniformGuess::doubt),
// each language's matrices together, every other uniform alone: what `init` may switch
// when its check run shows a blank original or a failing port.
struct GuessDoubt {
  std::string id;                  // "hlsl matrices", "glsl u_lightPos": the key of `switched`
  Language language = Language::hlsl;
  std::string uniforms;            // "'g_WorldViewProj', 'g_World'"
  std::string guessed;             // what the case binds now: "column vectors (no mul() names it)"
  std::string instead;             // what switching binds: the alternative's line, "g_World = {...}"
  std::vector<int> lines;          // the case file's lines binding them
  bool switched = false;           // the case binds the alternative
};

struct CaseDraft {
  std::string text;
  std::vector<std::string> todos;   // "line 14: bind 'u_roughness' (float) in [bindings.glsl]: ..."
  std::vector<GuessDoubt> doubts;   // in the order written: the original's first
};

// `case_path`: where the case will be written (its paths are made relative to where it
// resolves them from, scene/CaseFile.h shader_root_of). `images`: image files next to the
// shaders (absolute), candidates for the shaders' textures. `switched`: doubts (by id) whose
// alternative the case binds instead, each with why, for the binding's comment.
CaseDraft draft_case(const std::vector<SurveyedLanguage>& languages, const std::string& case_path,
                     const std::vector<std::string>& images, const std::map<std::string, std::string>& switched = {});

// The image files (PNG, EXR, HDR, TGA, DDS, JPEG) in a folder, sorted.
std::vector<std::string> images_in(const std::string& folder);

}  // namespace shaderbed
