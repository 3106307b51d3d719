// `shaderbed view` end to end, on a virtual X server (Xvfb): it draws the pixels `run`
// draws for the same cell on both backends and presents them with the backend's API (a
// Vulkan swapchain on a window without a GL context, or the window's GL context), B
// making the window again between the two; keys sent with xdotool change the shape, the
// variant and the fill, and its screenshots change with them (each the run's render of the
// new cell); an edited shader is drawn again (its speed is not asserted here), a planted compile
// error shows its file and line in the title and on stderr while the last good image
// stays, and a shader that crashes the compiler does not take the viewer down; without a
// display it says how to get one and exits 2.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ShellCommand.h"
#include "TempDir.h"
#include "ViewerSession.h"
#include "viewer/InspectionPanel.h"
#include "viewer/KeyMap.h"

namespace shaderbed::test {
namespace {

const fs::path kSource = SHADERBED_SOURCE_DIR;
const std::string kBinary = SHADERBED_BINARY;
constexpr int kSize = 128;   // small windows keep the area quick

// `run` draws the cells into DIR (its --out layout) and reports them in DIR/results.json.
nlohmann::json run_cells(const TempDir& dir, const std::string& filters) {
  const auto [status, out] = run_shell(kBinary + " run " + filters + " --size " + std::to_string(kSize) +
                                       " --repeat 0 -q --keep-images all --out " + (dir / "run") + " --json " + (dir / "results.json"));
  EXPECT_EQ(status, 0) << out;
  std::ifstream in(dir / "results.json");
  return nlohmann::json::parse(in, nullptr, false);
}

// The render's largest difference from the run's, as a share of the cell's interior
// tolerance (max_abs + max_rel |run|) over every pixel and channel: <= 1 is "the same".
double share_of_tolerance(const ImagePixels& view, const ImagePixels& run, const nlohmann::json& cell) {
  if (view.values.size() != run.values.size() || run.values.empty()) return INFINITY;
  const nlohmann::json& tolerance = cell["tolerance"];
  const double abs = tolerance.value("interior", 0.0), rel = tolerance.value("interior_rel", 0.0);
  if (abs <= 0) return INFINITY;
  double worst = 0;
  for (size_t i = 0; i < run.values.size(); ++i)
    worst = std::max(worst, std::abs(double(view.values[i]) - run.values[i]) / (abs + rel * std::abs(run.values[i])));
  return worst;
}

const nlohmann::json& cell_of(const nlohmann::json& results, const std::string& id) {
  static const nlohmann::json none = nlohmann::json::object();
  for (const nlohmann::json& r : results["results"])
    if (r["id"] == id) return r;
  ADD_FAILURE() << "no cell " << id;
  return none;
}

// `xvfb-run -a shaderbed view ... --screenshot FILE --frames N` against `run`'s render.
void expect_screenshot_is_the_runs_render(const std::string& language, const std::string& backend,
                                          const std::string& path, const std::string& case_name = "phong",
                                          const std::string& variant = "pixel") {
  TempDir dir("view_run");
  const nlohmann::json results =
      run_cells(dir, "--case " + case_name + " --variant " + variant + " --shape torus --lang " + language +
                                 " --backend " + backend);
  const std::string cell = case_name + "/" + variant + "/" + language + "/" + backend + "/" + path + "/torus";
  std::pair<int, std::string> viewed;
  {
    XvfbStartLock lock;   // xvfb-run -a and a concurrent test could pick the same display
    viewed = run_shell("xvfb-run -a " + kBinary + " view --case " + case_name + " --variant " + variant + " --shape torus --lang " + language +
                       " --backend " + backend + " --path " + path + " --size " + std::to_string(kSize) +
                       " --screenshot " + (dir / "view.png") + " --frames 3");
  }
  ASSERT_EQ(viewed.first, 0) << viewed.second;
  EXPECT_NE(viewed.second.find("3 frames"), std::string::npos) << viewed.second;
  // Presented with the backend's API: the PNG below is read back from a swapchain image
  // for vulkan (a window without a GL context), from the GL back buffer for gl.
  const auto says = [&](const std::string& text) { return viewed.second.find(text) != std::string::npos; };
  if (backend == "vulkan") {
    EXPECT_TRUE(says("presenting through a Vulkan swapchain (lavapipe, VK_KHR_")) << viewed.second;
    EXPECT_TRUE(says("the window has no GL context")) << viewed.second;
    EXPECT_FALSE(says("presenting through the window's GL context")) << viewed.second;
  } else {
    EXPECT_TRUE(says("presenting through the window's GL context (")) << viewed.second;
    EXPECT_FALSE(says("Vulkan swapchain")) << viewed.second;
  }
  EXPECT_FALSE(says("not read back")) << viewed.second;
  EXPECT_FALSE(says("cannot present")) << viewed.second;
  ASSERT_TRUE(fs::exists(dir / "view.png"));
  const ImagePixels view = read_exr(dir / "view.exr");
  const ImagePixels run = read_exr(dir / ("run/" + case_name + "/" + variant + "/torus/" + language + "-" + backend + "-" + path + ".exr"));
  ASSERT_EQ(view.width, kSize);
  EXPECT_GT(drawn_pixels(run), 1000u);
  EXPECT_LE(share_of_tolerance(view, run, cell_of(results, cell)), 1.0) << cell;
  EXPECT_EQ(differing_pixels(view, run), 0u) << "the same engine, the same scene: the same pixels (" << cell << ")";
  // The PNG is read back from the window: what the screen shows is the run's PNG.
  const auto png = [](const std::string& file) {
    auto image = read_image_file(file);
    return image ? *image : ImagePixels{};
  };
  const ImagePixels shown = png(dir / "view.png");
  EXPECT_EQ(shown.width, kSize);
  EXPECT_EQ(differing_pixels(shown, png(dir / ("run/" + case_name + "/" + variant + "/torus/" + language + "-" + backend + "-" + path + ".png"))),
            0u);
}

TEST(View, ScreenshotIsTheRunsRenderOnVulkan) { expect_screenshot_is_the_runs_render("hlsl", "vulkan", "spirv"); }

TEST(View, ScreenshotIsTheRunsRenderOnGl) { expect_screenshot_is_the_runs_render("glsl", "gl", "glsl"); }

// An SH case: the shape with its transfer texture and light uniforms (harness/prt).
TEST(View, AnShCaseIsTheRunsRender) { expect_screenshot_is_the_runs_render("glsl", "vulkan", "spirv", "sh", "texture"); }

// One draw path (run/CellDraw.h): a user's DX9 effect with a file texture, an attribute map
// (its normals and UVs on TEXCOORD5 and TEXCOORD2) and pass states (back faces culled, no
// depth test, so a draw without them shows the far side) draws alike under every command:
// `view` shows run's pixels, and every `hard` row of it draws and passes.
TEST(View, AUserEffectDrawsAlikeUnderRunViewAndHard) {
  TempDir dir("one_draw");
  const std::string cases = "--cases-dir " + (kSource / "tests" / "viewer" / "one_draw" / "cases").string() +
                            " --case textured_lambert";
  const nlohmann::json results = run_cells(dir, cases + " --shape sphere --lang hlsl --backend vulkan");
  const std::string cell = "textured_lambert/pixel/hlsl/vulkan/spirv/sphere";
  EXPECT_EQ(cell_of(results, cell).value("status", ""), "pass") << cell_of(results, cell).dump();
  std::pair<int, std::string> viewed;
  {
    XvfbStartLock lock;
    viewed = run_shell("xvfb-run -a " + kBinary + " view " + cases + " --shape sphere --lang hlsl --backend vulkan" +
                       " --size " + std::to_string(kSize) + " --screenshot " + (dir / "view.png") + " --frames 2");
  }
  ASSERT_EQ(viewed.first, 0) << viewed.second;
  const ImagePixels view = read_exr(dir / "view.exr");
  const ImagePixels run = read_exr(dir / "run/textured_lambert/pixel/sphere/hlsl-vulkan-spirv.exr");
  EXPECT_GT(drawn_pixels(run), 1000u);
  EXPECT_EQ(differing_pixels(view, run), 0u) << "view draws the effect as run does";

  const auto [status, hard] = run_shell(kBinary + " hard " + cases + " --size 33 --json " + (dir / "hard.json"));
  EXPECT_EQ(status, 0) << hard;
  std::ifstream in(dir / "hard.json");
  const nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
  ASSERT_TRUE(report.contains("rows")) << hard;
  EXPECT_FALSE(report["rows"].empty());
  for (const nlohmann::json& row : report["rows"])
    EXPECT_EQ(row.value("status", ""), "pass") << row.dump();
}

TEST(View, KeysChangeShapeVariantAndWireframe) {
  TempDir dir("view_keys");
  const nlohmann::json results =
      run_cells(dir, "--case phong --variant vertex,pixel --shape sphere,cube --lang hlsl --backend vulkan");
  VirtualDisplay display(dir);
  ASSERT_TRUE(display.ready());
  ViewerSession viewer(display, dir,
                       "--case phong --variant vertex --lang hlsl --backend vulkan --shape sphere --size " +
                           std::to_string(kSize) + " --out " + (dir / "shots"));
  ASSERT_TRUE(viewer.has_window()) << viewer.errors();
  const auto shot = [&](const std::string& keys) {
    if (!keys.empty()) viewer.keys(keys);
    const std::string stem = viewer.screenshot();
    EXPECT_FALSE(stem.empty()) << "after " << keys << ": " << viewer.output() << viewer.errors();
    return stem;
  };
  const std::string sphere = shot("");
  const std::string cube = shot("M");           // DirectX framework: next mesh
  const std::string pixel = shot("V");          // next vertex shader: the next variant
  const std::string wireframe = shot("y");      // Cg/GLSL frameworks: wireframe
  const std::string torus = shot("y greater greater");   // filled again, two shapes on
  const std::string title = viewer.title();
  EXPECT_EQ(viewer.quit(), 0) << viewer.errors();

  // Each screenshot is named after its cell, and is the run's render of that cell.
  EXPECT_EQ(sphere, dir / "shots/phong/vertex/sphere/hlsl-vulkan-spirv.view-1");
  EXPECT_EQ(cube, dir / "shots/phong/vertex/cube/hlsl-vulkan-spirv.view-1");
  EXPECT_EQ(pixel, dir / "shots/phong/pixel/cube/hlsl-vulkan-spirv.view-1");
  EXPECT_EQ(wireframe, dir / "shots/phong/pixel/cube/hlsl-vulkan-spirv.view-2");
  EXPECT_EQ(torus, dir / "shots/phong/pixel/torus/hlsl-vulkan-spirv.view-1");
  const auto image = [](const std::string& stem) { return read_exr(stem + ".exr"); };
  const auto run = [&](const std::string& variant, const std::string& shape) {
    return read_exr(dir / ("run/phong/" + variant + "/" + shape + "/hlsl-vulkan-spirv.exr"));
  };
  EXPECT_EQ(differing_pixels(image(sphere), run("vertex", "sphere")), 0u);
  EXPECT_EQ(differing_pixels(image(cube), run("vertex", "cube")), 0u);
  EXPECT_EQ(differing_pixels(image(pixel), run("pixel", "cube")), 0u);
  EXPECT_GT(differing_pixels(image(sphere), image(cube)), 500u);
  EXPECT_GT(differing_pixels(image(cube), image(pixel)), 0u) << "per vertex and per pixel Phong differ on the cube";
  // Wireframe: the cube's edges only, far fewer pixels drawn.
  const size_t filled = drawn_pixels(image(pixel)), lines = drawn_pixels(image(wireframe));
  EXPECT_GT(lines, 50u);
  EXPECT_LT(lines * 2, filled) << lines << " of " << filled;
  EXPECT_GT(drawn_pixels(image(torus)), 1000u);
  EXPECT_NE(title.find("shaderbed view: phong/pixel hlsl vulkan/spirv torus | pass"), std::string::npos) << title;
}

// Columns [x0, x0 + width) of an image.
ImagePixels columns(const ImagePixels& image, int x0, int width) {
  ImagePixels out{width, image.height, image.channels, {}};
  for (int y = 0; y < image.height; ++y)
    for (int x = x0; x < x0 + width && x < image.width; ++x)
      for (int c = 0; c < image.channels; ++c)
        out.values.push_back(image.values[(size_t(y) * image.width + x) * image.channels + c]);
  return out;
}

size_t count_of(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(View, BSwitchesBetweenTheSwapchainAndTheGlWindow) {
  TempDir dir("view_present");
  run_cells(dir, "--case phong --variant pixel --shape sphere --lang glsl");
  VirtualDisplay display(dir);
  ASSERT_TRUE(display.ready());
  ViewerSession viewer(display, dir,
                       "--case phong --variant pixel --lang glsl --backend vulkan --shape sphere --size " +
                           std::to_string(kSize) + " --out " + (dir / "shots"));
  ASSERT_TRUE(viewer.has_window()) << viewer.errors();
  const std::string on_vulkan = viewer.screenshot();
  viewer.keys("B");   // vulkan/spirv -> gl/glsl: a window with a GL context replaces the swapchain's
  ASSERT_TRUE(viewer.follow_new_window()) << viewer.errors();
  const std::string on_gl = viewer.screenshot();
  viewer.keys("b");   // back to vulkan/spirv, and to a swapchain
  ASSERT_TRUE(viewer.follow_new_window()) << viewer.errors();
  // The split view, through the swapchain: e and c at once, so the screenshot waits for
  // the window's resize and shows the split view, however the viewer batches the keys.
  const std::string split = viewer.screenshot("e");
  const std::string title = viewer.title();
  const std::string errors = viewer.errors();
  EXPECT_EQ(viewer.quit(), 0) << errors;

  // One window per API in turn, each saying how it presents.
  const std::string vulkan_says = "presenting through a Vulkan swapchain (lavapipe, VK_KHR_";
  const std::string gl_says = "presenting through the window's GL context (";
  EXPECT_EQ(count_of(errors, vulkan_says), 2u) << errors;
  EXPECT_EQ(count_of(errors, gl_says), 1u) << errors;
  EXPECT_LT(errors.find(vulkan_says), errors.find(gl_says)) << errors;
  EXPECT_LT(errors.find(gl_says), errors.rfind(vulkan_says)) << errors;
  EXPECT_EQ(errors.find("not read back"), std::string::npos) << errors;
  EXPECT_EQ(errors.find("cannot present"), std::string::npos) << errors;
  EXPECT_NE(title.find("glsl vulkan/spirv sphere | pass"), std::string::npos) << title;

  // What each window presented, read back, is the run's PNG of its cell.
  const auto png = [](const std::string& file) {
    auto image = read_image_file(file);
    return image ? *image : ImagePixels{};
  };
  const std::string run = dir / "run/phong/pixel/sphere/";
  EXPECT_EQ(on_vulkan, dir / "shots/phong/pixel/sphere/glsl-vulkan-spirv.view-1");
  EXPECT_EQ(on_gl, dir / "shots/phong/pixel/sphere/glsl-gl-glsl.view-1");
  EXPECT_EQ(split, dir / "shots/phong/pixel/sphere/glsl-vulkan-spirv.view-2");
  for (const auto& [shot, cell] : {std::pair{on_vulkan, std::string("glsl-vulkan-spirv")},
                                   std::pair{on_gl, std::string("glsl-gl-glsl")}}) {
    const ImagePixels shown = png(shot + ".png");
    EXPECT_EQ(shown.width, kSize) << shot;
    EXPECT_EQ(differing_pixels(shown, png(run + cell + ".png")), 0u) << shot;
    EXPECT_EQ(differing_pixels(read_exr(shot + ".exr"), read_exr(run + cell + ".exr")), 0u) << shot;
  }
  // The split view through the swapchain: render | reference | error, the panels the
  // screenshot writes from the frame itself, two black columns apart.
  const ImagePixels shown = png(split + ".png");
  ASSERT_EQ(shown.width, 3 * kSize + 4);
  ASSERT_EQ(shown.height, kSize);
  EXPECT_EQ(differing_pixels(columns(shown, 0, kSize), png(run + "glsl-vulkan-spirv.png")), 0u);
  EXPECT_EQ(differing_pixels(columns(shown, kSize + 2, kSize), png(split + ".reference.png")), 0u);
  EXPECT_EQ(differing_pixels(columns(shown, 2 * kSize + 4, kSize), png(split + ".error.png")), 0u);
  const ImagePixels gap = columns(shown, kSize, 2);
  EXPECT_TRUE(std::ranges::all_of(gap.values, [](float v) { return v == 0; })) << "the gap is black";
}

// A copy of the phong case and its GLSL shaders, to edit under the viewer.
std::string copy_phong(const TempDir& dir) {
  fs::create_directories(dir.path() / "cases");
  fs::create_directories(dir.path() / "glsl");
  fs::copy_file(kSource / "shaders/cases/phong.toml", dir.path() / "cases/phong.toml");
  for (const char* f : {"setup.vert", "phong.frag"}) fs::copy_file(kSource / "shaders/glsl" / f, dir.path() / "glsl" / f);
  return dir / "cases/phong.toml";
}

void edit(const std::string& file, const std::string& from, const std::string& to) {
  std::string text = read_text(file);
  const size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
}

TEST(View, LiveReloadOfAnEditedShaderAndAPlantedCompileError) {
  TempDir dir("view_reload");
  const std::string the_case = copy_phong(dir);
  const std::string shader = dir / "glsl/phong.frag";
  VirtualDisplay display(dir);
  ASSERT_TRUE(display.ready());
  ViewerSession viewer(display, dir,
                       "--case " + the_case + " --variant pixel --lang glsl --backend gl --size " +
                           std::to_string(kSize) + " --out " + (dir / "shots"));
  ASSERT_TRUE(viewer.has_window()) << viewer.errors();
  const std::string before = viewer.screenshot();
  ASSERT_FALSE(before.empty()) << viewer.errors();

  // About half the light, by a factor no earlier run has compiled (no cache can answer).
  const long stamp = long(std::chrono::system_clock::now().time_since_epoch().count() / 1000 % 1000000);
  const double factor = 0.5 + stamp * 1e-8;
  char literal[32];
  std::snprintf(literal, sizeof literal, "%.8f", factor);
  edit(shader, "fragColor = vec4(diffuse + specular, 1.0);",
       "fragColor = vec4(" + std::string(literal) + " * (diffuse + specular), 1.0);");
  ASSERT_TRUE(viewer.wait_for_output("reloaded " + shader)) << viewer.output() << viewer.errors();
  const std::string halved = viewer.screenshot();
  const ImagePixels a = read_exr(before + ".exr"), b = read_exr(halved + ".exr");
  ASSERT_EQ(a.values.size(), b.values.size());
  size_t lit = 0;
  for (size_t i = 0; i < a.values.size(); i += 4)
    for (size_t c = 0; c < 3; ++c)
      if (a.values[i + 3] != 0 && a.values[i + c] > 0.01) {
        EXPECT_NEAR(b.values[i + c], factor * a.values[i + c], 1e-6 + 1e-6 * a.values[i + c]) << i;
        ++lit;
      }
  EXPECT_GT(lit, 1000u);

  // A compile error on line 8: shown with its file and line; the last good image stays up.
  edit(shader, "    vec3 lightDirection;", "    not a declaration;\n    vec3 lightDirection;");
  ASSERT_TRUE(viewer.wait_for_errors("phong.frag:8")) << viewer.errors();
  EXPECT_NE(viewer.errors().find(shader + ":8: compile:"), std::string::npos) << viewer.errors();
  EXPECT_NE(viewer.errors().find("the last good image stays up"), std::string::npos) << viewer.errors();
  std::string title;
  wait_until([&] { return (title = viewer.title()).find("phong.frag:8") != std::string::npos; }, 5);
  EXPECT_NE(title.find("ERROR " + shader + ":8: compile:"), std::string::npos) << title;
  EXPECT_NE(title.find("(last good image shown)"), std::string::npos) << title;
  const std::string kept = viewer.screenshot();
  EXPECT_EQ(differing_pixels(read_exr(kept + ".exr"), b), 0u) << "the last good image stays";

  // Fixed again: drawn, and the error is gone from the title.
  edit(shader, "    not a declaration;\n", "");
  ASSERT_TRUE(wait_until([&] { return viewer.title().find("ERROR") == std::string::npos; }, 10)) << viewer.title();

  // The case file is watched too: an error in it is shown with its line until it is fixed.
  edit(the_case, "power = 7.0", "power = \"seven\"");
  ASSERT_TRUE(wait_until([&] { return viewer.title().find("ERROR " + the_case + ":8:") != std::string::npos; }, 10))
      << viewer.title();
  edit(the_case, "power = \"seven\"", "power = 7.0");
  ASSERT_TRUE(wait_until([&] { return viewer.title().find("ERROR") == std::string::npos; }, 10)) << viewer.title();
  EXPECT_EQ(viewer.quit(), 0) << viewer.errors();
}

TEST(View, AShaderThatCrashesTheCompilerDoesNotTakeTheViewerDown) {
  TempDir dir("view_crash");
  fs::create_directories(dir.path() / "cases");
  fs::create_directories(dir.path() / "hlsl");
  fs::copy_file(kSource / "shaders/cases/lambert.toml", dir.path() / "cases/lambert.toml");
  for (const char* f : {"setup_vs.hlsl", "lambert_ps.hlsl"})
    fs::copy_file(kSource / "shaders/hlsl" / f, dir.path() / "hlsl" / f);
  const std::string shader = dir / "hlsl/lambert_ps.hlsl";
  const std::string good = read_text(shader);
  VirtualDisplay display(dir);
  ASSERT_TRUE(display.ready());
  ViewerSession viewer(display, dir,
                       "--case " + (dir / "cases/lambert.toml") + " --variant pixel --lang hlsl --size " +
                           std::to_string(kSize) + " --out " + (dir / "shots"));
  ASSERT_TRUE(viewer.has_window()) << viewer.errors();
  const std::string first = viewer.screenshot();
  ASSERT_FALSE(first.empty()) << viewer.errors();
  // glslang 12 dereferences null on an HLSL entry parameter without a name (tests/run/isolation_test.cpp).
  std::ofstream(shader, std::ios::trunc) << "// A pixel stage with an unnamed parameter (crashes glslang 12).\n"
                                            "float4 main(int) : COLOR0 { return 1; }\n";
  ASSERT_TRUE(viewer.wait_for_errors("compiler crashed: signal 11 (SIGSEGV)")) << viewer.errors();
  const std::string after = viewer.screenshot();   // still alive, the last good image up
  EXPECT_EQ(differing_pixels(read_exr(after + ".exr"), read_exr(first + ".exr")), 0u);
  std::ofstream(shader, std::ios::trunc) << good;
  ASSERT_TRUE(wait_until([&] { return viewer.title().find("| pass") != std::string::npos; }, 10)) << viewer.title();
  EXPECT_EQ(viewer.quit(), 0) << viewer.errors();
}

// The pixel inspector (i, a right click, --inspect): the cell's shader at one pixel, line
// by line, by its double twin, with what each value matches in a differential case's
// original. tinted_diffuse/light_negated plants -L in its last line: lit from above in
// the original, the port's upper half is dark, and its planted line's value matches
// nothing there.
const std::string kPlanted = "--cases-dir " + (kSource / "tests" / "differential" / "cases").string() +
                             " --case tinted_diffuse --variant light_negated --lang glsl --backend vulkan --shape sphere";

// The inspection's listing on stdout, from its "inspect ..., pixel (x, y)" head to the next blank-free block.
std::string listing_of(const std::string& out, int x, int y) {
  const std::string head = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") of ";
  const size_t at = out.find(head);
  if (at == std::string::npos) return "";
  const size_t start = out.rfind("inspect ", at);
  const size_t next = out.find("\ninspect ", at);
  return out.substr(start, next == std::string::npos ? std::string::npos : next + 1 - start);
}

TEST(View, InspectPrintsThePixelsLinesValuesAndWhatMatchesNothing) {
  TempDir dir("view_inspect");
  std::pair<int, std::string> viewed;
  {
    XvfbStartLock lock;
    viewed = run_shell("xvfb-run -a " + kBinary + " view " + kPlanted + " --size 64 --inspect 32,16 --inspect 0,0" +
                       " --screenshot " + (dir / "view.png") + " 2>/dev/null");
  }
  ASSERT_EQ(viewed.first, 0) << viewed.second;
  const std::string& out = viewed.second;
  const std::string listing = listing_of(out, 32, 16);
  ASSERT_FALSE(listing.empty()) << out;
  EXPECT_NE(listing.find("inspect tinted_diffuse/light_negated glsl vulkan/spirv sphere, pixel (32, 16) of 64x64"),
            std::string::npos) << listing;
  EXPECT_NE(listing.find("values matched against the original"), std::string::npos) << listing;
  // Every executed line of the fragment shader, with its values.
  EXPECT_NE(listing.find("light_negated.frag:13  vec3 n = normalize(vNormal);"), std::string::npos) << listing;
  EXPECT_NE(listing.find("      n = ("), std::string::npos) << listing;
  // The planted line: its value departs from everything the original computed.
  const size_t planted = listing.find("light_negated.frag:14");
  ASSERT_NE(planted, std::string::npos) << listing;
  EXPECT_NE(listing.find("matches nothing", planted), std::string::npos) << listing;
  EXPECT_EQ(listing.substr(0, planted).find("matches nothing"), std::string::npos)
      << "the lines before the planted one match the original:\n" << listing;
  // Outside the shape: one line, no listing; the title carries the last answer.
  EXPECT_NE(out.find("pixel (0, 0) of 64x64 (row 0 at the top): pixel (0, 0) is not covered by the shape\n"),
            std::string::npos) << out;
  EXPECT_NE(out.find("| pixel (0, 0) is not covered by the shape\n"), std::string::npos) << out;
}

// The inspector in the window: the screenshot after an inspection is the one without it
// but for a dark panel over the half of the image away from the pixel, with the listing's
// text in it and the line that matches nothing in the warm colour.
TEST(View, InspectShowsTheListingInAPanelInTheWindow) {
  TempDir dir("view_inspect_panel");
  std::pair<int, std::string> with, without;
  {
    XvfbStartLock lock;
    with = run_shell("xvfb-run -a " + kBinary + " view " + kPlanted + " --size " + std::to_string(kSize) +
                     " --inspect 64,32 --screenshot " + (dir / "with.png") + " 2>&1");
  }
  {
    XvfbStartLock lock;
    without = run_shell("xvfb-run -a " + kBinary + " view " + kPlanted + " --size " + std::to_string(kSize) +
                        " --screenshot " + (dir / "without.png") + " 2>&1");
  }
  ASSERT_EQ(with.first, 0) << with.second;
  ASSERT_EQ(without.first, 0) << without.second;
  ASSERT_NE(listing_of(with.second, 64, 32).find("matches nothing"), std::string::npos) << with.second;
  const auto png = [](const std::string& file) {
    auto image = read_image_file(file);
    return image ? *image : ImagePixels{};
  };
  const ImagePixels a = png(dir / "with.png"), b = png(dir / "without.png");
  ASSERT_EQ(a.width, kSize);
  ASSERT_EQ(a.height, kSize);
  ASSERT_EQ(a.values.size(), b.values.size());
  ASSERT_GE(a.channels, 3);
  const auto rgb = [](const ImagePixels& image, int x, int y) {
    const size_t at = (size_t(y) * size_t(image.width) + size_t(x)) * size_t(image.channels);
    return viewer::Rgb{uint8_t(std::lround(image.values[at] * 255)), uint8_t(std::lround(image.values[at + 1] * 255)),
                       uint8_t(std::lround(image.values[at + 2] * 255))};
  };
  // Pixel (64, 32) is in the upper half: the panel is over the lower one, which it darkens.
  int changed_above = 0, changed_below = 0, brighter_below = 0, text = 0, warm = 0, text_without = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const viewer::Rgb p = rgb(a, x, y), q = rgb(b, x, y);
      text_without += q == viewer::kPanelTextColour || q == viewer::kPanelDepartsColour;
      if (y < kSize / 2) {
        changed_above += p != q;
        continue;
      }
      changed_below += p != q;
      text += p == viewer::kPanelTextColour;
      warm += p == viewer::kPanelDepartsColour;
      brighter_below += p != viewer::kPanelTextColour && p != viewer::kPanelDepartsColour && p[0] > q[0] + 1;
    }
  EXPECT_EQ(changed_above, 0) << "the half with the inspected pixel is not covered";
  EXPECT_GT(changed_below, kSize * kSize / 4) << "the panel darkens the lower half";
  EXPECT_GT(text, 50) << "the listing's text";
  EXPECT_GT(warm, 50) << "the line that matches nothing";
  EXPECT_EQ(text_without, 0) << "no text without an inspection";
  EXPECT_LT(brighter_below, kSize * 4) << "only the glyphs' edges are brighter than the image";
}

TEST(View, TheIKeyAndARightClickInspectThePixelUnderTheCursor) {
  TempDir dir("view_inspect_keys");
  VirtualDisplay display(dir);
  ASSERT_TRUE(display.ready());
  constexpr int kFrame = 4;   // viewer/Presenter.h: the window is the image and a frame around it
  ViewerSession viewer(display, dir, kPlanted + " --size 64 --out " + (dir / "shots"));
  ASSERT_TRUE(viewer.has_window()) << viewer.errors();
  ASSERT_FALSE(viewer.screenshot().empty()) << viewer.errors();   // the first frame is up
  viewer.pointer(kFrame + 32, kFrame + 16);
  viewer.keys("i");
  ASSERT_TRUE(viewer.wait_for_output("pixel (32, 16) of 64x64")) << viewer.output() << viewer.errors();
  ASSERT_TRUE(wait_until([&] { return listing_of(viewer.output(), 32, 16).find("matches nothing") != std::string::npos; }, 20))
      << viewer.output();
  EXPECT_TRUE(wait_until([&] { return viewer.title().find("| pixel (32, 16): light_negated.frag:14") != std::string::npos; }, 10))
      << viewer.title();
  // Split view: a right click on the reference panel inspects the same pixel of the cell.
  ASSERT_FALSE(viewer.screenshot("e").empty()) << viewer.errors();   // waits for the wider window
  viewer.click(kFrame + 64 + 2 + 30, kFrame + 20);
  ASSERT_TRUE(viewer.wait_for_output("pixel (30, 20) of 64x64")) << viewer.output() << viewer.errors();
  viewer.click(kFrame + 64, kFrame + 20);   // the gap between the panels
  EXPECT_TRUE(viewer.wait_for_output("is not over the image")) << viewer.output();
  EXPECT_EQ(viewer.quit(), 0) << viewer.errors();
}

TEST(View, WithoutADisplayItSaysSoAndExits2) {
  const auto [status, out] = run_shell("env -u DISPLAY -u WAYLAND_DISPLAY " + kBinary + " view --case phong");
  EXPECT_EQ(status, 2) << out;
  EXPECT_NE(out.find("view needs a display"), std::string::npos) << out;
  EXPECT_NE(out.find("xvfb-run -a shaderbed view"), std::string::npos) << out;
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1) << "one line: " << out;
}

TEST(View, BadInputIsExit2BeforeAnyWindow) {
  const auto [status, out] = run_shell("env -u DISPLAY " + kBinary + " view --case phong --variant nope");
  EXPECT_EQ(status, 2) << out;
  EXPECT_NE(out.find("has no variant 'nope'"), std::string::npos) << out;
}

TEST(View, HelpPrintsTheKeyTable) {
  const auto [status, out] = run_shell(kBinary + " view --help");
  EXPECT_EQ(status, 0) << out;
  for (const viewer::KeyRow& row : viewer::key_rows()) EXPECT_NE(out.find(row.keys), std::string::npos) << row.keys;
  EXPECT_NE(out.find("--screenshot"), std::string::npos);
}

}  // namespace
}  // namespace shaderbed::test
