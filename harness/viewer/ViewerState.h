#pragma once
// What the viewer shows: the cell (variant, language, backend and path, shape of one
// case), how it is looked at (wireframe, Gouraud, split view, scale, zoom, spin, light)
// and the case's parameters as stepped from the keyboard. Keys change it through pure
// functions, so the key handling is tested without a window.
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "backends/Backend.h"
#include "core/Error.h"
#include "scene/CaseFile.h"
#include "scene/Scene.h"
#include "viewer/KeyMap.h"

namespace shaderbed::viewer {

struct Parameter {
  std::string name;
  std::vector<double> values;
  bool operator==(const Parameter&) const = default;
};

// What a case offers for the keys to step through.
struct CellMenu {
  std::string case_name;
  std::vector<std::string> variants;
  std::vector<std::vector<Language>> languages;   // per variant: hlsl, cg, glsl (the book's order) as written
  std::vector<std::string> shapes;                 // sphere, cube, cone, torus
  std::vector<Parameter> parameters;               // the case file's values, by name
  bool operator==(const CellMenu&) const = default;
};

CellMenu menu_of(const Case& c);

struct ViewerState {
  CellMenu menu;
  size_t variant = 0;
  Language language = Language::hlsl;
  std::string backend = "vulkan";
  ShaderPath path = ShaderPath::spirv;
  size_t shape = 0;

  bool wireframe = false;
  bool gouraud = false;   // the reference's per-vertex Lambert instead of the shader
  bool split = false;     // render | reference | error heat map
  double scale = 1;       // the shape's world scale
  double zoom = 1;        // the eye's distance is divided by it
  double spin_degrees = 0;   // about the world's +Y
  glm::dvec3 light{0, 1, 0};   // toward the directional light; the point light sits 50 units along it

  std::vector<Parameter> parameters;   // current values
  size_t selected = 0;                 // index into parameter_components()

  const std::string& variant_name() const { return menu.variants[variant]; }
  const std::string& shape_name() const { return menu.shapes[shape]; }
  // What decides the image (everything but the split view and the selected parameter).
  bool same_image(const ViewerState& other) const;
};

// The command line's choice; "" = the default (the case's first variant; hlsl, else the
// variant's first language; vulkan; the backend's first path for the language; sphere).
struct CellChoice {
  std::string variant, language, backend, path, shape;
};

// Bad input (a variant, language, backend, path or shape the case does not have) is an
// error naming what there is.
Result<ViewerState> initial_state(const Case& c, const CellChoice& choice);

// The state for a reloaded case: the same cell where the case still has it, and the
// stepped parameters kept where the file did not change them.
ViewerState with_case(const ViewerState& old, const Case& reloaded);

// (backend, path) pairs a language can be drawn on, in the order B steps through them.
std::vector<std::pair<std::string, ShaderPath>> backend_paths_of(Language language);

enum class Effect { none, redraw, screenshot, inspect, help, quit };

// The key's action applied to the state; what the caller must do next.
Effect apply(ViewerState& state, ViewerAction action);
Effect handle_key(ViewerState& state, const KeyPress& key);

// A drag of (dx, dy) window pixels (y down) in a window `height` pixels tall turns the
// light like a trackball: the direction that faces the viewer moves with the cursor, and
// a drag the window's height turns it half a turn.
void drag_light(ViewerState& state, double dx, double dy, double height);

// Mouse wheel steps (positive: towards the screen, zoom in).
void scroll_zoom(ViewerState& state, double steps);

// The scene the state draws, `size` pixels square: the run's scene (scene/Scene.h) when
// nothing is scaled, spun, zoomed or moved, so the image is `run`'s.
SceneSetup scene_of(const ViewerState& state, int size);

// The case with the state's parameters (for the renderer and the reference).
Case with_parameters(const Case& c, const ViewerState& state);

// Every parameter component the selection steps through: "diffuse.r", "power".
std::vector<std::string> parameter_components(const ViewerState& state);

// "diffuse=1,1,1 specular=1,1,1 power=[7]": the selected component in brackets.
std::string parameters_text(const ViewerState& state);

// "phong/pixel hlsl vulkan/spirv sphere" and the view's modes ("wireframe", "Gouraud",
// "scale 1.2", ...) when set.
std::string cell_text(const ViewerState& state);

}  // namespace shaderbed::viewer
