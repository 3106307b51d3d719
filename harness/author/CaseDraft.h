#pragma once
// The case file `shaderbed init` writes: a differential case (no model: the first
// language's Vulkan SPIR-V render is the reference), one `pixel` variant holding each
// language's files and entries, every uniform bound with a guess (author/BindingGuess.h)
// and a comment saying why, GLSL vertex inputs mapped by name, textures bound to the image
// next to the shader when one is the obvious choice. What it cannot guess is a TODO
// written so the file still loads: a commented-out binding with a placeholder, and a
// line in `todos` naming the case file's line.
#include <string>
#include <vector>

#include "author/ShaderSurvey.h"

namespace shaderbed {

struct CaseDraft {
  std::string text;
  std::vector<std::string> todos;   // "line 14: bind 'u_roughness' (float) in [bindings.glsl]: ..."
};

// `case_path`: where the case will be written (its paths are made relative to where it
// resolves them from, scene/CaseFile.h shader_root_of). `images`: image files next to the
// shaders (absolute), candidates for the shaders' textures.
CaseDraft draft_case(const std::vector<SurveyedLanguage>& languages, const std::string& case_path,
                     const std::vector<std::string>& images);

// The image files (PNG, EXR, HDR, TGA, DDS, JPEG) in a folder, sorted.
std::vector<std::string> images_in(const std::string& folder);

}  // namespace shaderbed
