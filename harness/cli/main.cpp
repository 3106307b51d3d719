// shaderbed: compile a lighting shader, render it on real drivers, diff it against a
// double-precision CPU reference.
#include <fmt/format.h>

#include "cli/commands/ColourChoice.h"
#include "cli/commands/Command.h"
#include "cli/commands/HelpFormat.h"
#include "cli/commands/ParseErrorLine.h"

int main(int argc, char** argv) {
  CLI::App app{"shaderbed: a cross-API shader test bench. Compiles HLSL, Cg and GLSL lighting shaders to SPIR-V, "
               "renders them on Vulkan (lavapipe) and OpenGL (OSMesa or EGL) and compares every image with a "
               "double-precision CPU reference."};
  app.name("shaderbed");   // help's usage line, not the build folder's path of argv[0]
  app.require_subcommand(0, 1);   // none only with --version
  const shaderbed::Command commands[] = {shaderbed::add_run_command(app), shaderbed::add_eval_command(app),
                                          shaderbed::add_merge_command(app),
                                          shaderbed::add_stats_command(app), shaderbed::add_sweep_command(app),
                                          shaderbed::add_hard_command(app),
                                          shaderbed::add_init_command(app),
                                          shaderbed::add_port_command(app), shaderbed::add_explain_command(app),
                                          shaderbed::add_cell_worker_command(app),
                                          shaderbed::add_compile_stages_command(app),
                                          shaderbed::add_bench_command(app), shaderbed::add_devices_command(app),
                                          shaderbed::add_view_command(app), shaderbed::add_view_compile_command(app),
                                          shaderbed::add_sh_command(app), shaderbed::add_help_command(app),
                                          shaderbed::add_completion_command(app)};
  shaderbed::add_cache_options(app);
  shaderbed::add_vulkan_device_option(app);
  shaderbed::add_gl_platform_options(app);
  shaderbed::add_colour_option(app);
  shaderbed::add_version_flag(app);
  shaderbed::format_help(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One line, like every other refusal (CLI11's own text is a paragraph with no name).
    fmt::print(stderr, "shaderbed: {}\n", shaderbed::parse_error_line(app, e));
    return shaderbed::kExitBadInput;
  }
  for (const shaderbed::Command& c : commands)
    if (c.app->parsed()) return c.run();
  fmt::print(stderr, "shaderbed: a command is required (shaderbed --help lists them)\n");
  return shaderbed::kExitBadInput;
}
