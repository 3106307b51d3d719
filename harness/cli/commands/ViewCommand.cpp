// `shaderbed view`: one cell in a window, drawn as `run` draws it, with the book's test-bed
// keys, the reference and the error beside it, and live reload (harness/viewer/).
#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include "cli/commands/Command.h"
#include "core/ThisExecutable.h"
#include "run/Runner.h"
#include "viewer/CompileProbe.h"
#include "viewer/KeyMap.h"
#include "viewer/Viewer.h"

namespace shaderbed {

Command add_view_command(CLI::App& app) {
  auto args = std::make_shared<viewer::ViewerOptions>();
  viewer::ViewerOptions& o = *args;
  CLI::App* cmd = app.add_subcommand(
      "view",
      "Show one cell in a window, drawn by the backend `run` uses and judged against the same reference: the book's "
      "test bed, with the reference and the error beside the render and live reload of the case and its shaders. "
      "Needs a display (under none: xvfb-run -a shaderbed view ...)");
  cmd->add_option("--case", o.case_name,
                  "Case name (NAME.toml in --cases-dir) or case file; default: phong, else the first case");
  cmd->add_option("--variant", o.choice.variant, "Variant; default: the case's first");
  cmd->add_option("--lang", o.choice.language, "Language: hlsl, cg, glsl; default: hlsl, else the variant's first");
  cmd->add_option("--backend", o.choice.backend, "Backend: vulkan, gl; default: vulkan");
  cmd->add_option("--path", o.choice.path,
                  "Path on the backend: spirv (vulkan, gl), glsl (gl, GLSL only), cross (gl); default: the backend's "
                  "first for the language");
  cmd->add_option("--shape", o.choice.shape, "Shape: sphere, cube, cone, torus; default: sphere");
  cmd->add_option("--param", o.params,
                  "Override a case parameter: name=value or name=v1,v2,v3 (repeatable); the keys step from there");
  cmd->add_option("--size", o.size, "Image width and height in pixels (as run --size)")
      ->capture_default_str()
      ->check(CLI::Range(8, 4096));
  cmd->add_option("--out", o.out_dir,
                  "Folder for the screenshot key's files, laid out as run --out: DIR/<case>/<variant>/<shape>/")
      ->capture_default_str();
  cmd->add_flag("--split", o.split, "Start in the split view: render | reference | error heat map");
  cmd->add_option("--screenshot", o.screenshot,
                  "Draw --frames frames, write FILE (.png: what the window shows; .exr beside it: the render, exact; "
                  "with --split the reference and error images too) and exit, without any interaction");
  cmd->add_option("--frames", o.frames, "Frames to draw before --screenshot is written")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  auto pixels = std::make_shared<std::vector<std::string>>();
  cmd->add_option("--inspect", *pixels,
                  "Inspect pixel X,Y (the image's, row 0 at the top) once the first frame is drawn, as the i key does: "
                  "the lines its shader executed there with their values, by its double twin, on stdout (repeatable; "
                  "with --screenshot, before it exits)")
      ->check([](const std::string& text) -> std::string {
        int x = 0, y = 0;
        char end = 0;
        return std::sscanf(text.c_str(), "%d,%d%c", &x, &y, &end) == 2 ? "" : "expected X,Y (two whole numbers)";
      });
  cmd->add_option("--cases-dir", o.cases_dir, "Folder of case files")->default_str(default_cases_dir());
  cmd->footer("Keys (also printed by h in the window):\n" + viewer::key_table(2) +
              "\nThe window title shows the cell, its verdict and max error against the reference, the parameters "
              "(the selected one in brackets) and the draw and frame times; a compile error shows there with its file "
              "and line, and on stderr, while the last good image stays up.");

  return {cmd, [args, pixels] {
            viewer::ViewerOptions options = *args;
            for (const std::string& text : *pixels) {
              int x = 0, y = 0;
              std::sscanf(text.c_str(), "%d,%d", &x, &y);
              options.inspect.emplace_back(x, y);
            }
            if (options.cases_dir.empty()) options.cases_dir = default_cases_dir();
            options.probe_binary = this_executable().string();
            return viewer::run_viewer(options);
          }};
}

Command add_view_compile_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("__view-compile", "");
  cmd->group("");   // hidden: the viewer's compile probe (viewer/CompileProbe.h), started by `shaderbed view`
  return {cmd, [] { return viewer::serve_compile_probe(); }};
}

}  // namespace shaderbed
