#pragma once
// The viewer's keys: one table, from which the key handling looks actions up and from
// which `h` and `shaderbed view --help` print, so what is printed is what is bound.
//
// The book's three test beds disagree (its §7.1-§7.3): the
// Cg and GLSL frameworks bind y/Y wireframe, g/G fixed-function light or shader, s/S
// scale, >/< shape, q/Q quit; the DirectX framework binds V/P next vertex/pixel shader, M
// next mesh, W/S zoom, A/D spin. They collide on S (scale up, or zoom out): s/S keep the
// Cg/GLSL meaning and zoom is W/w. Keys are case-sensitive, as in the Cg/GLSL frameworks:
// the upper-case key goes forward or up, the lower-case one back or down.
#include <optional>
#include <string>
#include <vector>

namespace shaderbed::viewer {

enum class ViewerAction {
  toggle_wireframe,
  toggle_gouraud,
  scale_down,
  scale_up,
  next_shape,
  previous_shape,
  next_variant,
  previous_variant,
  next_language,
  previous_language,
  next_backend,
  previous_backend,
  zoom_in,
  zoom_out,
  spin_left,
  spin_right,
  light_brighter,
  light_dimmer,
  diffuse_yellow,
  diffuse_white,
  next_parameter,
  previous_parameter,
  parameter_up,
  parameter_down,
  toggle_split,
  screenshot,
  inspect,
  reset,
  help,
  quit,
};

enum class NamedKey { none, tab, escape, left, right, up, down, f1 };

// A key as the window reports it: a typed character with Shift already applied ('y', 'Y',
// '>', '+'), or a key that types nothing (Tab, the arrows, Esc, F1) with its Shift state.
struct KeyPress {
  char32_t character = 0;
  NamedKey named = NamedKey::none;
  bool shift = false;

  static KeyPress typed(char32_t c) { return {.character = c}; }
  static KeyPress key(NamedKey k, bool with_shift = false) { return {.named = k, .shift = with_shift}; }
  bool operator==(const KeyPress&) const = default;
};

// One printed row: the keys as printed, what they do, where they come from, and the
// bindings behind it (a row like "mouse drag" has none: the window handles it).
struct KeyRow {
  std::string keys;
  std::string what;
  std::string origin;
  std::vector<std::pair<KeyPress, ViewerAction>> bindings;
};

const std::vector<KeyRow>& key_rows();

// The action a key is bound to, if any.
std::optional<ViewerAction> action_for(const KeyPress& key);

// The table as text, one row per line, indented by `indent` spaces (for `h` and --help).
std::string key_table(int indent = 2);

// The table as Markdown (docs/viewer.md's key table is written from it).
std::string key_table_markdown();

}  // namespace shaderbed::viewer
