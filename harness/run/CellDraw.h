#pragma once
// Draws one cell: the case's uniforms, textures, vertex attribute map and the program's
// render states bound for the cell's language, drawn by one backend into a float target.
// Every command that draws a cell (run, view, hard, sweep, bench, init, port) draws
// through here, so a case draws alike under all of them.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "backends/Backend.h"
#include "scene/CaseFile.h"
#include "scene/Scene.h"

namespace shaderbed {

// What a reference adds to every draw of its group (an SH case's light coefficients and
// generated textures, drawn on its mesh with the transfer streams).
struct DrawAdditions {
  const Mesh* mesh = nullptr;   // null: the shape's
  NamedValues values;
  std::map<std::string, std::shared_ptr<const Texture>> textures;
};

// One channel of one 8-bit image file moved a stored step (CaseTextures::step_texels).
struct TexelStep {
  std::string texture;
  int channel = 0;
};

struct CellDraw {
  const Case& c;
  Language language;
  ShaderPath path;
  const CompiledProgram& program;
  const Mesh& mesh;                              // the shape (DrawAdditions::mesh stands in for it)
  const SceneSetup& scene;
  const Texture* lut = nullptr;                  // the variant's generated LUT, if it has one
  const DrawAdditions* additions = nullptr;
  const NamedValues* values = nullptr;           // null: the scene's quantities and the case's parameters
  const BindingTable* bindings = nullptr;        // null: the case's for the language (a counterfactual's own)
  bool flip_images = false;                      // every 2D image file upside down (a counterfactual)
  const TexelStep* texel_step = nullptr;         // one texture channel a step off (the texel bound's draws)
  TimingRequest timing{.warmup = 0, .runs = 0};
  std::optional<FillMode> fill;                  // the viewer's wireframe
  // Set: the case's bindings no variant reads become the drawn cell's warnings; the texts
  // are the case's other variants in this language (CaseUniforms::unused_bindings).
  const std::vector<std::string>* other_sources = nullptr;
};

struct DrawnCell {
  Image image;
  RenderTimings timings;
  std::string texture_note;            // CaseTextures::reference_note: "" when no image file is read
  std::vector<std::string> warnings;   // unused bindings (CellDraw::other_sources)
};

// Errors say which binding, texture or backend step failed; a backend's name its own.
Result<DrawnCell> draw_cell(Backend& backend, const CellDraw& draw);

}  // namespace shaderbed
