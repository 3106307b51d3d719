#include "viewer/ViewerState.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/Primitives.h"

namespace shaderbed::viewer {
namespace {

constexpr double kScaleStep = 1.1;     // s / S
constexpr double kZoomStep = 1.1;      // W / w, one wheel step
constexpr double kSpinStep = 10;       // degrees, a / d
constexpr double kLightStep = 1.25;    // l / L
constexpr double kParameterStep = 1.1; // + / -
constexpr double kFromZero = 0.05;     // + / - on a zero parameter
constexpr double kPointLightDistance = 50;   // the book's point light at (0, 50, 0)

// The book's order of the three test beds: DirectX/HLSL, Cg, GLSL.
constexpr Language kLanguageOrder[] = {Language::hlsl, Language::cg, Language::glsl};

size_t step(size_t index, size_t count, int by) {
  if (count == 0) return 0;
  return size_t((long(index) + by + long(count)) % long(count));
}

const std::vector<Language>& languages_of(const ViewerState& s) { return s.menu.languages[s.variant]; }

// After the variant changed: the same language if the variant has it, else its first.
void keep_language(ViewerState& s) {
  const auto& languages = languages_of(s);
  if (std::ranges::find(languages, s.language) == languages.end() && !languages.empty()) s.language = languages.front();
}

// After the language changed: the same backend and path if they take it, else the backend's first path.
void keep_path(ViewerState& s) {
  const std::vector<ShaderPath> paths = backend_paths(s.backend, s.language);
  if (std::ranges::find(paths, s.path) == paths.end()) s.path = paths.front();
}

struct Component {
  size_t parameter, index;
};

std::vector<Component> components(const ViewerState& s) {
  std::vector<Component> out;
  for (size_t p = 0; p < s.parameters.size(); ++p)
    for (size_t i = 0; i < s.parameters[p].values.size(); ++i) out.push_back({p, i});
  return out;
}

double stepped(const std::string& name, double v, bool up) {
  // A lookup texture's size or row count is a whole number of texels: doubled or halved.
  if (name.starts_with("lut_")) return up ? v * 2 : std::max(1.0, std::floor(v / 2));
  if (v == 0) return up ? kFromZero : -kFromZero;
  const bool grows = (v > 0) == up;
  return grows ? v * kParameterStep : v / kParameterStep;
}

// The colour parameters: three or four components (diffuse, specular, ambient, ...).
bool colour(const Parameter& p) { return p.values.size() == 3 || p.values.size() == 4; }

Parameter* diffuse_of(ViewerState& s) {
  for (Parameter& p : s.parameters)
    if (p.name == "diffuse" && colour(p)) return &p;
  for (Parameter& p : s.parameters)
    if (colour(p)) return &p;
  return nullptr;
}

std::string number(double v) { return fmt::format("{:.4g}", v); }

}  // namespace

CellMenu menu_of(const Case& c) {
  CellMenu menu;
  menu.case_name = c.name;
  for (const Variant& v : c.variants) {
    menu.variants.push_back(v.name);
    std::vector<Language> languages;
    for (Language l : kLanguageOrder)
      if (v.shaders.contains(l)) languages.push_back(l);
    menu.languages.push_back(std::move(languages));
  }
  menu.shapes = shape_names();
  for (const auto& [name, values] : c.params) menu.parameters.push_back({name, values});
  return menu;
}

bool ViewerState::same_image(const ViewerState& o) const {
  return menu == o.menu && variant == o.variant && language == o.language && backend == o.backend && path == o.path &&
         shape == o.shape && wireframe == o.wireframe && gouraud == o.gouraud && scale == o.scale && zoom == o.zoom &&
         spin_degrees == o.spin_degrees && light == o.light && parameters == o.parameters;
}

std::vector<std::pair<std::string, ShaderPath>> backend_paths_of(Language language) {
  std::vector<std::pair<std::string, ShaderPath>> out;
  for (const char* backend : {"vulkan", "gl"})
    for (ShaderPath path : backend_paths(backend, language)) out.emplace_back(backend, path);
  return out;
}

Result<ViewerState> initial_state(const Case& c, const CellChoice& choice) {
  ViewerState s;
  s.menu = menu_of(c);
  s.parameters = s.menu.parameters;
  if (s.menu.variants.empty()) return fail(ErrorStage::options, "case '" + c.name + "' has no variants");
  const auto names = [](const auto& list, auto name) {
    std::string text;
    for (const auto& item : list) text += (text.empty() ? "" : ", ") + std::string(name(item));
    return text;
  };
  const auto identity = [](const std::string& s) { return s; };
  if (!choice.variant.empty()) {
    const auto it = std::ranges::find(s.menu.variants, choice.variant);
    if (it == s.menu.variants.end())
      return fail(ErrorStage::options, fmt::format("case '{}' has no variant '{}' (it has {})", c.name, choice.variant,
                                         names(s.menu.variants, identity)));
    s.variant = size_t(it - s.menu.variants.begin());
  }
  const auto& languages = languages_of(s);
  if (languages.empty())
    return fail(ErrorStage::options, fmt::format("variant '{}' of case '{}' names no shaders", s.variant_name(), c.name));
  s.language = languages.front();
  if (!choice.language.empty()) {
    auto language = parse_language(choice.language);
    if (!language) return std::unexpected(language.error());
    if (std::ranges::find(languages, *language) == languages.end())
      return fail(ErrorStage::options, fmt::format("variant '{}' of case '{}' has no {} shaders (it has {})", s.variant_name(),
                                         c.name, choice.language, names(languages, [](Language l) { return to_string(l); })));
    s.language = *language;
  }
  if (!choice.backend.empty()) {
    if (choice.backend != "vulkan" && choice.backend != "gl")
      return fail(ErrorStage::options, "unknown backend '" + choice.backend + "' (backends: vulkan, gl)");
    s.backend = choice.backend;
  }
  const std::vector<ShaderPath> paths = backend_paths(s.backend, s.language);
  s.path = paths.front();
  if (!choice.path.empty()) {
    const auto it = std::ranges::find_if(paths, [&](ShaderPath p) { return choice.path == to_string(p); });
    if (it == paths.end())
      return fail(ErrorStage::options, fmt::format("backend {} has no path '{}' for {} (paths: {})", s.backend, choice.path,
                                         to_string(s.language), names(paths, [](ShaderPath p) { return to_string(p); })));
    s.path = *it;
  }
  if (!choice.shape.empty()) {
    const auto it = std::ranges::find(s.menu.shapes, choice.shape);
    if (it == s.menu.shapes.end())
      return fail(ErrorStage::options,
                  fmt::format("unknown shape '{}' (shapes: {})", choice.shape, names(s.menu.shapes, identity)));
    s.shape = size_t(it - s.menu.shapes.begin());
  }
  return s;
}

ViewerState with_case(const ViewerState& old, const Case& reloaded) {
  ViewerState s = old;
  s.menu = menu_of(reloaded);
  if (s.menu.variants.empty()) return old;   // the caller reports an unusable case
  const auto variant = std::ranges::find(s.menu.variants, old.variant_name());
  s.variant = variant == s.menu.variants.end() ? 0 : size_t(variant - s.menu.variants.begin());
  keep_language(s);
  keep_path(s);
  s.parameters.clear();
  for (const Parameter& p : s.menu.parameters) {
    const auto before = std::ranges::find(old.menu.parameters, p.name, &Parameter::name);
    const auto now = std::ranges::find(old.parameters, p.name, &Parameter::name);
    // The file's value unless the file left it as it was and the keys changed it.
    const bool unchanged_in_file = before != old.menu.parameters.end() && before->values == p.values;
    s.parameters.push_back(unchanged_in_file && now != old.parameters.end() && now->values.size() == p.values.size()
                               ? *now
                               : p);
  }
  // The same parameter component stays selected, wherever it now is.
  const std::vector<std::string> before = parameter_components(old), after = parameter_components(s);
  const auto kept = before.empty() ? after.end() : std::ranges::find(after, before[std::min(old.selected, before.size() - 1)]);
  s.selected = kept != after.end() ? size_t(kept - after.begin()) : std::min(s.selected, std::max<size_t>(after.size(), 1) - 1);
  return s;
}

Effect apply(ViewerState& s, ViewerAction action) {
  using A = ViewerAction;
  switch (action) {
    case A::toggle_wireframe: s.wireframe = !s.wireframe; return Effect::redraw;
    case A::toggle_gouraud: s.gouraud = !s.gouraud; return Effect::redraw;
    case A::scale_down: s.scale /= kScaleStep; return Effect::redraw;
    case A::scale_up: s.scale *= kScaleStep; return Effect::redraw;
    case A::next_shape: s.shape = step(s.shape, s.menu.shapes.size(), 1); return Effect::redraw;
    case A::previous_shape: s.shape = step(s.shape, s.menu.shapes.size(), -1); return Effect::redraw;
    case A::next_variant:
    case A::previous_variant:
      s.variant = step(s.variant, s.menu.variants.size(), action == A::next_variant ? 1 : -1);
      keep_language(s);
      keep_path(s);
      return Effect::redraw;
    case A::next_language:
    case A::previous_language: {
      const auto& languages = languages_of(s);
      const size_t at = size_t(std::ranges::find(languages, s.language) - languages.begin());
      s.language = languages[step(at, languages.size(), action == A::next_language ? 1 : -1)];
      keep_path(s);
      return Effect::redraw;
    }
    case A::next_backend:
    case A::previous_backend: {
      const auto pairs = backend_paths_of(s.language);
      const auto it = std::ranges::find(pairs, std::pair{s.backend, s.path});
      const size_t at = it == pairs.end() ? 0 : size_t(it - pairs.begin());
      std::tie(s.backend, s.path) = pairs[step(at, pairs.size(), action == A::next_backend ? 1 : -1)];
      return Effect::redraw;
    }
    case A::zoom_in: s.zoom *= kZoomStep; return Effect::redraw;
    case A::zoom_out: s.zoom /= kZoomStep; return Effect::redraw;
    case A::spin_left: s.spin_degrees = std::fmod(s.spin_degrees - kSpinStep, 360.0); return Effect::redraw;
    case A::spin_right: s.spin_degrees = std::fmod(s.spin_degrees + kSpinStep, 360.0); return Effect::redraw;
    case A::light_brighter:
    case A::light_dimmer: {
      bool any = false;
      for (Parameter& p : s.parameters)
        if (colour(p)) {
          any = true;
          for (size_t i = 0; i < std::min<size_t>(p.values.size(), 3); ++i)
            p.values[i] = action == A::light_brighter ? p.values[i] * kLightStep : p.values[i] / kLightStep;
        }
      return any ? Effect::redraw : Effect::none;
    }
    case A::diffuse_yellow:
    case A::diffuse_white: {
      Parameter* p = diffuse_of(s);
      if (!p) return Effect::none;
      p->values[0] = p->values[1] = 1;
      p->values[2] = action == A::diffuse_yellow ? 0 : 1;
      return Effect::redraw;
    }
    case A::next_parameter:
    case A::previous_parameter: {
      const size_t count = components(s).size();
      if (count == 0) return Effect::none;
      s.selected = step(s.selected, count, action == A::next_parameter ? 1 : -1);
      return Effect::redraw;   // the title shows the selection
    }
    case A::parameter_up:
    case A::parameter_down: {
      const auto all = components(s);
      if (all.empty()) return Effect::none;
      const Component& c = all[std::min(s.selected, all.size() - 1)];
      Parameter& p = s.parameters[c.parameter];
      p.values[c.index] = stepped(p.name, p.values[c.index], action == A::parameter_up);
      return Effect::redraw;
    }
    case A::toggle_split: s.split = !s.split; return Effect::redraw;
    case A::screenshot: return Effect::screenshot;
    case A::inspect: return Effect::inspect;
    case A::reset: {
      ViewerState fresh;
      fresh.menu = s.menu;
      fresh.variant = s.variant, fresh.language = s.language, fresh.backend = s.backend, fresh.path = s.path;
      fresh.shape = s.shape, fresh.split = s.split, fresh.parameters = s.menu.parameters;
      s = std::move(fresh);
      return Effect::redraw;
    }
    case A::help: return Effect::help;
    case A::quit: return Effect::quit;
  }
  return Effect::none;
}

Effect handle_key(ViewerState& state, const KeyPress& key) {
  const auto action = action_for(key);
  return action ? apply(state, *action) : Effect::none;
}

void drag_light(ViewerState& s, double dx, double dy, double height) {
  if ((dx == 0 && dy == 0) || height <= 0) return;
  const Camera camera = scene_of(s, 1).camera;
  const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
  const glm::dvec3 right = glm::normalize(glm::cross(camera.up, forward));   // left-handed view: x to the right
  const glm::dvec3 up = glm::cross(forward, right);
  const glm::dvec3 motion = dx * right - dy * up;   // window y grows downwards
  const glm::dvec3 axis = glm::normalize(glm::cross(-forward, motion));
  const double angle = std::numbers::pi * std::hypot(dx, dy) / height;
  const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), angle, axis);
  s.light = glm::normalize(glm::dvec3(turn * glm::dvec4(s.light, 0.0)));
}

void scroll_zoom(ViewerState& s, double steps) { s.zoom *= std::pow(kZoomStep, steps); }

SceneSetup scene_of(const ViewerState& s, int size) {
  SceneSetup scene;
  scene.width = scene.height = size;
  // Only what the keys changed departs from the run's scene, so an untouched view is
  // the run's exactly (no rotate(0) * scale(1) rounding).
  if (s.spin_degrees != 0 || s.scale != 1)
    scene.world = glm::rotate(glm::dmat4(1.0), glm::radians(s.spin_degrees), glm::dvec3(0, 1, 0)) *
                  glm::scale(glm::dmat4(1.0), glm::dvec3(s.scale));
  if (s.zoom != 1) scene.camera.eye = scene.camera.target + (scene.camera.eye - scene.camera.target) / s.zoom;
  if (s.light != glm::dvec3(0, 1, 0)) {
    scene.lights.direction = glm::normalize(s.light);
    scene.lights.position = kPointLightDistance * scene.lights.direction;
  }
  return scene;
}

Case with_parameters(const Case& c, const ViewerState& s) {
  Case out = c;
  for (const Parameter& p : s.parameters)
    if (out.params.contains(p.name)) out.params[p.name] = p.values;
  return out;
}

std::vector<std::string> parameter_components(const ViewerState& s) {
  static const char* const kRgba[] = {"r", "g", "b", "a"};
  std::vector<std::string> out;
  for (const Component& c : components(s)) {
    const Parameter& p = s.parameters[c.parameter];
    if (p.values.size() == 1) out.push_back(p.name);
    else if (colour(p)) out.push_back(p.name + "." + kRgba[c.index]);
    else out.push_back(fmt::format("{}[{}]", p.name, c.index));
  }
  return out;
}

std::string parameters_text(const ViewerState& s) {
  const auto all = components(s);
  std::string text;
  size_t flat = 0;
  for (const Parameter& p : s.parameters) {
    text += (text.empty() ? "" : " ") + p.name + "=";
    for (size_t i = 0; i < p.values.size(); ++i, ++flat) {
      const bool selected = flat == std::min(s.selected, all.empty() ? 0 : all.size() - 1);
      text += (i ? "," : "") + (selected ? "[" + number(p.values[i]) + "]" : number(p.values[i]));
    }
  }
  return text;
}

std::string cell_text(const ViewerState& s) {
  std::string text = fmt::format("{}/{} {} {}/{} {}", s.menu.case_name, s.variant_name(), to_string(s.language),
                                 s.backend, to_string(s.path), s.shape_name());
  if (s.gouraud) text += " Gouraud";
  if (s.wireframe) text += " wireframe";
  if (s.scale != 1) text += fmt::format(" scale {:.3g}", s.scale);
  if (s.zoom != 1) text += fmt::format(" zoom {:.3g}", s.zoom);
  if (s.spin_degrees != 0) text += fmt::format(" spin {:.0f}°", s.spin_degrees);
  if (s.light != glm::dvec3(0, 1, 0))
    text += fmt::format(" light ({:.2f}, {:.2f}, {:.2f})", s.light.x, s.light.y, s.light.z);
  return text;
}

}  // namespace shaderbed::viewer
