// The viewer's keys as pure functions of the state, without a window: the book's test-bed
// keys (the book's §7), how their collisions are resolved, the
// parameter keys, the light under the mouse, and the scene a state draws.
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "viewer/KeyMap.h"
#include "viewer/ViewerState.h"

namespace shaderbed::viewer {
namespace {

// A phong-like case: three variants, one of them without Cg; no files are read.
Case test_case() {
  Case c;
  c.name = "phong";
  c.path = "/cases/phong.toml";
  c.model = "phong";
  const auto files = [](const char* stem) { return ShaderFiles{.vertex = std::string(stem) + ".v", .fragment = std::string(stem) + ".f"}; };
  c.variants = {
      {.name = "vertex", .mode = LightingMode::per_vertex,
       .shaders = {{Language::hlsl, files("a")}, {Language::glsl, files("b")}, {Language::cg, files("c")}}},
      {.name = "pixel", .shaders = {{Language::hlsl, files("d")}, {Language::glsl, files("e")}, {Language::cg, files("f")}}},
      {.name = "pixel_glsl_only", .shaders = {{Language::glsl, files("g")}}},
  };
  c.params = {{"diffuse", {1, 1, 1}}, {"power", {7}}, {"specular", {1, 1, 1}}};
  return c;
}

ViewerState start(const CellChoice& choice = {}) {
  auto s = initial_state(test_case(), choice);
  EXPECT_TRUE(s) << s.error().to_string();
  return *s;
}

Effect press(ViewerState& s, char32_t c) { return handle_key(s, KeyPress::typed(c)); }
Effect press(ViewerState& s, NamedKey k, bool shift = false) { return handle_key(s, KeyPress::key(k, shift)); }

TEST(ViewerKeys, DefaultsAreTheBooksStartingPoint) {
  const ViewerState s = start();
  EXPECT_EQ(s.variant_name(), "vertex");
  EXPECT_EQ(s.language, Language::hlsl);   // the DirectX/HLSL framework first
  EXPECT_EQ(s.backend, "vulkan");
  EXPECT_EQ(s.path, ShaderPath::spirv);
  EXPECT_EQ(s.shape_name(), "sphere");     // the Cg/GLSL frameworks start on the sphere
  EXPECT_FALSE(s.wireframe);
  EXPECT_FALSE(s.gouraud);
}

TEST(ViewerKeys, CgAndGlslFrameworkKeys) {
  ViewerState s = start();
  EXPECT_EQ(press(s, 'y'), Effect::redraw);
  EXPECT_TRUE(s.wireframe);
  press(s, 'Y');
  EXPECT_FALSE(s.wireframe) << "y and Y both toggle wireframe / filled";
  press(s, 'g');
  EXPECT_TRUE(s.gouraud);
  press(s, 'G');
  EXPECT_FALSE(s.gouraud);
  press(s, 's');
  EXPECT_LT(s.scale, 1);
  press(s, 'S');
  press(s, 'S');
  EXPECT_GT(s.scale, 1) << "S scales up (the Cg/GLSL meaning), not zoom out (the DirectX one)";
  EXPECT_EQ(s.zoom, 1);
  for (const char* shape : {"cube", "cone", "torus", "sphere"}) {
    press(s, '>');
    EXPECT_EQ(s.shape_name(), shape);
  }
  press(s, '<');
  EXPECT_EQ(s.shape_name(), "torus");
  EXPECT_EQ(press(s, 'q'), Effect::quit);
  EXPECT_EQ(press(s, 'Q'), Effect::quit);
  EXPECT_EQ(press(s, NamedKey::escape), Effect::quit);
  EXPECT_EQ(press(s, 'h'), Effect::help);
}

TEST(ViewerKeys, DirectXFrameworkKeys) {
  ViewerState s = start();
  press(s, 'M');
  EXPECT_EQ(s.shape_name(), "cube") << "M: next mesh";
  press(s, 'V');
  EXPECT_EQ(s.variant_name(), "pixel") << "V: next vertex shader, here the next variant";
  press(s, 'P');
  EXPECT_EQ(s.language, Language::cg) << "P: next pixel shader, here the next language (hlsl, cg, glsl)";
  press(s, 'P');
  EXPECT_EQ(s.language, Language::glsl);
  press(s, 'p');
  EXPECT_EQ(s.language, Language::cg);
  press(s, 'W');
  EXPECT_GT(s.zoom, 1);
  press(s, 'w');
  press(s, 'w');
  EXPECT_LT(s.zoom, 1);
  press(s, 'd');
  EXPECT_EQ(s.spin_degrees, 10);
  press(s, 'a');
  press(s, 'A');
  EXPECT_EQ(s.spin_degrees, -10);
  press(s, NamedKey::right);
  EXPECT_EQ(s.spin_degrees, 0) << "the arrows spin too (Ch. 9)";
  press(s, NamedKey::f1);
  EXPECT_EQ(s.variant_name(), "pixel_glsl_only") << "F1 cycles the shaders (Ch. 9)";
}

TEST(ViewerKeys, AVariantWithoutTheLanguageFallsBackToOneItHas) {
  ViewerState s = start({.variant = "pixel", .language = "cg"});
  press(s, 'V');
  EXPECT_EQ(s.variant_name(), "pixel_glsl_only");
  EXPECT_EQ(s.language, Language::glsl);
  press(s, 'v');
  EXPECT_EQ(s.variant_name(), "pixel");
  EXPECT_EQ(s.language, Language::glsl) << "the language is kept where the variant has it";
}

TEST(ViewerKeys, BackendKeyStepsThroughEveryBackendAndPath) {
  ViewerState s = start({.language = "glsl"});
  std::vector<std::string> seen;
  for (int i = 0; i < 4; ++i) {
    seen.push_back(s.backend + "/" + to_string(s.path));
    press(s, 'B');
  }
  EXPECT_EQ(seen, (std::vector<std::string>{"vulkan/spirv", "gl/glsl", "gl/spirv", "gl/cross"}));
  EXPECT_EQ(s.backend + "/" + to_string(s.path), "vulkan/spirv");
  press(s, 'b');
  EXPECT_EQ(s.backend + "/" + to_string(s.path), "gl/cross");
  // HLSL has no native GL path: the path falls back to the backend's first.
  s = start({.language = "glsl", .backend = "gl", .path = "glsl"});
  press(s, 'P');   // glsl -> hlsl
  EXPECT_EQ(s.language, Language::hlsl);
  EXPECT_EQ(s.backend, "gl");
  EXPECT_EQ(s.path, ShaderPath::spirv);
}

TEST(ViewerKeys, ParametersAreSelectedAndStepped) {
  ViewerState s = start();
  EXPECT_EQ(parameter_components(s),
            (std::vector<std::string>{"diffuse.r", "diffuse.g", "diffuse.b", "power", "specular.r", "specular.g",
                                      "specular.b"}));
  EXPECT_EQ(parameters_text(s), "diffuse=[1],1,1 power=7 specular=1,1,1");
  for (int i = 0; i < 3; ++i) press(s, NamedKey::tab);
  EXPECT_EQ(parameters_text(s), "diffuse=1,1,1 power=[7] specular=1,1,1");
  press(s, '+');
  EXPECT_DOUBLE_EQ(s.parameters[1].values[0], 7 * 1.1);
  press(s, '-');
  press(s, NamedKey::down);
  EXPECT_DOUBLE_EQ(s.parameters[1].values[0], 7 / 1.1);
  press(s, NamedKey::tab, /*shift=*/true);
  press(s, '[');
  EXPECT_EQ(parameters_text(s).substr(0, 15), "diffuse=1,[1],1");
  // The book's Phong handleKey: m yellow, n white; l/L the light's intensity.
  press(s, 'm');
  EXPECT_EQ(s.parameters[0].values, (std::vector<double>{1, 1, 0}));
  press(s, 'n');
  EXPECT_EQ(s.parameters[0].values, (std::vector<double>{1, 1, 1}));
  press(s, 'l');
  EXPECT_EQ(s.parameters[0].values, (std::vector<double>{1.25, 1.25, 1.25}));
  EXPECT_EQ(s.parameters[2].values, (std::vector<double>{1.25, 1.25, 1.25}));
  EXPECT_DOUBLE_EQ(s.parameters[1].values[0], 7 / 1.1) << "the exponent is no intensity";
  press(s, 'L');
  EXPECT_EQ(s.parameters[0].values, (std::vector<double>{1, 1, 1}));
  // From zero a step is 0.05, either way.
  s.parameters[1].values[0] = 0;
  s.selected = 3;
  press(s, '+');
  EXPECT_DOUBLE_EQ(s.parameters[1].values[0], 0.05);
  // A LUT's size doubles and halves.
  s.parameters.push_back({"lut_size", {64}});
  s.selected = parameter_components(s).size() - 1;
  press(s, '+');
  EXPECT_EQ(s.parameters.back().values[0], 128);
  press(s, '-');
  press(s, '-');
  EXPECT_EQ(s.parameters.back().values[0], 32);
  s.parameters.pop_back();
  // r puts everything back.
  press(s, 'W');
  press(s, 'y');
  EXPECT_EQ(press(s, 'r'), Effect::redraw);
  EXPECT_EQ(s.parameters, s.menu.parameters);
  EXPECT_EQ(s.zoom, 1);
  EXPECT_FALSE(s.wireframe);
}

TEST(ViewerKeys, SplitViewScreenshotAndUnboundKeys) {
  ViewerState s = start();
  EXPECT_EQ(press(s, 'e'), Effect::redraw);
  EXPECT_TRUE(s.split);
  EXPECT_EQ(press(s, 'c'), Effect::screenshot);
  const ViewerState before = s;
  EXPECT_EQ(press(s, 'z'), Effect::none);
  EXPECT_TRUE(s.same_image(before));
  // The split view and the selected parameter do not change the image: no new frame.
  press(s, 'e');
  press(s, NamedKey::tab);
  EXPECT_TRUE(s.same_image(before));
  press(s, 'M');
  EXPECT_FALSE(s.same_image(before));
}

TEST(ViewerKeys, EveryKeyIsBoundOnceAndThePrintedTableIsTheBoundOne) {
  std::set<std::pair<char32_t, std::pair<int, bool>>> keys;
  for (const KeyRow& row : key_rows())
    for (const auto& [key, action] : row.bindings) {
      EXPECT_TRUE(keys.insert({key.character, {int(key.named), key.shift}}).second)
          << "bound twice: " << row.keys << " (" << int(key.character) << ")";
      EXPECT_EQ(action_for(key), action);
    }
  const std::string table = key_table();
  for (const KeyRow& row : key_rows()) {
    EXPECT_NE(table.find(row.keys), std::string::npos) << row.keys;
    EXPECT_NE(table.find(row.what), std::string::npos) << row.what;
  }
  EXPECT_NE(key_table_markdown().find("render \\| reference \\| error"), std::string::npos) << key_table_markdown();
}

TEST(ViewerKeys, TheViewerDocShowsTheBoundTable) {
  std::ifstream in(std::string(SHADERBED_SOURCE_DIR) + "/docs/viewer.md");
  std::stringstream readme;
  readme << in.rdbuf();
  EXPECT_NE(readme.str().find(key_table_markdown()), std::string::npos)
      << "docs/viewer.md's key table is not the bound one; it should read:\n" << key_table_markdown();
}

TEST(ViewerState, AnUntouchedViewIsTheRunsScene) {
  const SceneSetup run;
  const SceneSetup view = scene_of(start(), 256);
  EXPECT_EQ(view.world, run.world);
  EXPECT_EQ(view.camera.eye, run.camera.eye);
  EXPECT_EQ(view.lights.direction, run.lights.direction);
  EXPECT_EQ(view.lights.position, run.lights.position);
  EXPECT_EQ(view.width, 256);
}

TEST(ViewerState, ScaleSpinZoomAndTheLightMoveTheScene) {
  ViewerState s = start();
  press(s, 'S');
  press(s, 'd');
  press(s, 'W');
  const SceneSetup scene = scene_of(s, 64);
  EXPECT_NEAR(glm::length(glm::dvec3(scene.world * glm::dvec4(1, 0, 0, 0))), 1.1, 1e-12);
  const glm::dvec3 x = glm::dvec3(scene.world * glm::dvec4(1, 0, 0, 0)) / 1.1;
  EXPECT_NEAR(x.x, std::cos(glm::radians(10.0)), 1e-12);
  const SceneSetup run;
  EXPECT_NEAR(glm::length(scene.camera.eye), glm::length(run.camera.eye) / 1.1, 1e-9);
  // The point light follows the directional one, at the book's 50 units.
  s.light = glm::normalize(glm::dvec3(1, 1, 0));
  EXPECT_NEAR(glm::length(scene_of(s, 64).lights.position), 50, 1e-12);
}

TEST(ViewerState, DraggingMovesTheLightWithTheCursor) {
  ViewerState s = start();
  const Camera camera = scene_of(s, 64).camera;
  const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
  const glm::dvec3 right = glm::normalize(glm::cross(camera.up, forward));
  drag_light(s, 40, 0, 400);   // to the right
  EXPECT_GT(glm::dot(s.light, right), 0.1) << "the light moves to the right on screen";
  EXPECT_NEAR(glm::length(s.light), 1, 1e-12);
  // A drag of the window's height turns the light half a turn.
  ViewerState t = start();
  const glm::dvec3 before = t.light;
  drag_light(t, 0, 400, 400);
  EXPECT_NEAR(glm::dot(t.light, before), -1, 1e-9);
}

TEST(ViewerState, BadChoicesNameWhatThereIs) {
  const Case c = test_case();
  auto bad = initial_state(c, {.variant = "pixel_lut"});
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("vertex, pixel, pixel_glsl_only"), std::string::npos) << bad.error().message;
  bad = initial_state(c, {.variant = "pixel_glsl_only", .language = "hlsl"});
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("has no hlsl shaders (it has glsl)"), std::string::npos) << bad.error().message;
  bad = initial_state(c, {.language = "hlsl", .backend = "gl", .path = "glsl"});
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("paths: spirv, cross"), std::string::npos) << bad.error().message;
  EXPECT_FALSE(initial_state(c, {.shape = "teapot"}));
  EXPECT_FALSE(initial_state(c, {.backend = "d3d9"}));
}

TEST(ViewerState, AReloadedCaseKeepsTheCellAndTheSteppedParametersTheFileLeftAlone) {
  ViewerState s = start({.variant = "pixel", .language = "cg", .shape = "torus"});
  s.selected = 3;
  press(s, '+');   // power 7.7
  press(s, 'm');   // diffuse yellow
  Case edited = test_case();
  edited.params["diffuse"] = {0.5, 0.5, 0.5};   // the file changed diffuse, not power
  edited.params["roughness"] = {0.3};
  const ViewerState r = with_case(s, edited);
  EXPECT_EQ(r.variant_name(), "pixel");
  EXPECT_EQ(r.language, Language::cg);
  EXPECT_EQ(r.shape_name(), "torus");
  EXPECT_EQ(parameters_text(r).find("diffuse=0.5,0.5,0.5"), 0u) << parameters_text(r);
  EXPECT_NE(parameters_text(r).find("power=[7.7]"), std::string::npos) << parameters_text(r);
  EXPECT_NE(parameters_text(r).find("roughness=0.3"), std::string::npos) << parameters_text(r);
  // A variant the file dropped: the first one instead.
  Case fewer = test_case();
  fewer.variants.erase(fewer.variants.begin() + 1);
  EXPECT_EQ(with_case(s, fewer).variant_name(), "vertex");
}

}  // namespace
}  // namespace shaderbed::viewer
