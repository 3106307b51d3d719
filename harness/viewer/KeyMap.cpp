#include "viewer/KeyMap.h"

#include <algorithm>

#include <fmt/format.h>

namespace shaderbed::viewer {
namespace {

using A = ViewerAction;

KeyPress c(char32_t ch) { return KeyPress::typed(ch); }
KeyPress k(NamedKey key, bool shift = false) { return KeyPress::key(key, shift); }

std::vector<KeyRow> make_rows() {
  const char* cg_glsl = "Cg, GLSL";
  const char* ours = "shaderbed";
  return {
      {"y, Y", "wireframe / filled", cg_glsl, {{c('y'), A::toggle_wireframe}, {c('Y'), A::toggle_wireframe}}},
      {"g, G", "Gouraud (the reference's vertex Lambert) / shader", cg_glsl,
       {{c('g'), A::toggle_gouraud}, {c('G'), A::toggle_gouraud}}},
      {"s / S", "scale the shape down / up", cg_glsl, {{c('s'), A::scale_down}, {c('S'), A::scale_up}}},
      {"> / <", "next / previous shape (sphere, cube, cone, torus)", cg_glsl,
       {{c('>'), A::next_shape}, {c('<'), A::previous_shape}}},
      {"M", "next shape", "DirectX (next mesh)", {{c('M'), A::next_shape}}},
      {"V / v, F1", "next / previous variant", "DirectX (V: next vertex shader), Ch. 9 (F1)",
       {{c('V'), A::next_variant}, {c('v'), A::previous_variant}, {k(NamedKey::f1), A::next_variant}}},
      {"P / p", "next / previous language (hlsl, cg, glsl)", "DirectX (P: next pixel shader)",
       {{c('P'), A::next_language}, {c('p'), A::previous_language}}},
      {"B / b", "next / previous backend and path", ours,
       {{c('B'), A::next_backend}, {c('b'), A::previous_backend}}},
      {"W / w", "zoom in / out", "DirectX (W; its S scales here)", {{c('W'), A::zoom_in}, {c('w'), A::zoom_out}}},
      {"a / d, Left / Right", "spin the shape left / right", "DirectX (A, D), Ch. 9 (arrows)",
       {{c('a'), A::spin_left}, {c('A'), A::spin_left}, {c('d'), A::spin_right}, {c('D'), A::spin_right},
        {k(NamedKey::left), A::spin_left}, {k(NamedKey::right), A::spin_right}}},
      {"l / L", "light intensity up / down (colours x1.25, /1.25)", "Cg (Phong's handleKey)",
       {{c('l'), A::light_brighter}, {c('L'), A::light_dimmer}}},
      {"m / n", "diffuse colour yellow / white", "Cg (Phong's handleKey)",
       {{c('m'), A::diffuse_yellow}, {c('n'), A::diffuse_white}}},
      {"Tab / Shift+Tab, ] / [", "select the next / previous parameter component", ours,
       {{k(NamedKey::tab), A::next_parameter}, {k(NamedKey::tab, true), A::previous_parameter},
        {c(']'), A::next_parameter}, {c('['), A::previous_parameter}}},
      {"+ / -, Up / Down", "step it up / down (x1.1, /1.1; 0.05 from 0; LUT x2, /2)", ours,
       {{c('+'), A::parameter_up}, {c('='), A::parameter_up}, {c('-'), A::parameter_down},
        {k(NamedKey::up), A::parameter_up}, {k(NamedKey::down), A::parameter_down}}},
      {"e", "split view: render | reference | error heat map", ours, {{c('e'), A::toggle_split}}},
      {"c", "screenshot: PNG and EXR under --out", ours, {{c('c'), A::screenshot}}},
      {"i", "inspect the pixel under the cursor: its shader's lines and values (stdout)", ours,
       {{c('i'), A::inspect}}},
      {"r", "reset the view, the light and the parameters", ours, {{c('r'), A::reset}}},
      {"h, H", "print this table", "Cg, GLSL (help)", {{c('h'), A::help}, {c('H'), A::help}}},
      {"q, Q, Esc", "quit", cg_glsl, {{c('q'), A::quit}, {c('Q'), A::quit}, {k(NamedKey::escape), A::quit}}},
      {"mouse drag", "move the light (left button)", ours, {}},
      {"mouse wheel", "zoom", ours, {}},
      {"right click", "inspect the pixel clicked, as i", ours, {}},
  };
}

}  // namespace

const std::vector<KeyRow>& key_rows() {
  static const std::vector<KeyRow> rows = make_rows();
  return rows;
}

std::optional<ViewerAction> action_for(const KeyPress& key) {
  for (const KeyRow& row : key_rows())
    for (const auto& [bound, action] : row.bindings)
      if (bound == key) return action;
  return std::nullopt;
}

std::string key_table(int indent) {
  size_t keys_width = 0, what_width = 0;
  for (const KeyRow& row : key_rows()) {
    keys_width = std::max(keys_width, row.keys.size());
    what_width = std::max(what_width, row.what.size());
  }
  std::string text = fmt::format("{:{}}{:<{}}  {:<{}}  {}\n", "", indent, "key", keys_width, "action", what_width,
                                 "from (the book's test beds, App. C)");
  for (const KeyRow& row : key_rows())
    text += fmt::format("{:{}}{:<{}}  {:<{}}  {}\n", "", indent, row.keys, keys_width, row.what, what_width, row.origin);
  return text;
}

std::string key_table_markdown() {
  std::string text = "| key | action | from (the book's test beds, App. C) |\n|---|---|---|\n";
  const auto cell = [](std::string s) {   // a '|' would end the cell
    for (size_t at = s.find('|'); at != std::string::npos; at = s.find('|', at + 2)) s.replace(at, 1, "\\|");
    return s;
  };
  for (const KeyRow& row : key_rows())
    text += fmt::format("| `{}` | {} | {} |\n", row.keys, cell(row.what), cell(row.origin));
  return text;
}

}  // namespace shaderbed::viewer
